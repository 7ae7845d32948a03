#include "trainer_ui/review/ReadableTrainees.h"

namespace colonosim::app {

std::vector<std::string> readableTrainees(db::Records& records, const db::Actor& actor)
{
    std::vector<std::string> out;
    for (const db::UserRow& u : records.listUsers(actor)) {
        if (u.role == db::Role::Student) {
            out.push_back(u.name);
        }
    }
    return out;
}

}  // namespace colonosim::app
