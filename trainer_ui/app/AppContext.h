#pragma once
/// \file
/// What every screen of the trainer shares: the open records and the person
/// logged in. Screens read and write only through `records`, which enforces
/// authorization for `actor`; they never open the database themselves.

#include "db/Database.h"
#include "db/Records.h"

#include <filesystem>

namespace colonosim::app {

struct AppContext {
    db::Database& database;
    db::Records& records;
    db::Actor actor;                  ///< the person logged in
    std::filesystem::path exportDir;  ///< default folder offered for reports, cases and backups
};

}  // namespace colonosim::app
