// A session's stored trace comes back through Records::sessionTrace exactly
// as it was stored, so the session can be replayed; an unknown session is
// refused with a sentence naming it. The case a session ran on reads back too.
#include "db/Database.h"
#include "db/Records.h"
#include "db/StoredTrace.h"
#include "tests/db/TempDir.h"

#include <gtest/gtest.h>

namespace {

using namespace colonosim;

TEST(SessionTrace, TheStoredTraceReadsBackBitForBit)
{
    test::TempDir dir;
    db::Database database(dir / "records.sqlite");
    db::Records records(database);
    const db::Actor admin = records.bootstrapAdministrator("root", "root-password");
    records.addUser(admin, "ada", db::Role::Student, "ada-password");
    const db::Actor ada = records.authenticate("ada", "ada-password");

    procedure::InputTrace trace;
    for (int k = 0; k < 500; ++k) {
        procedure::InputSample sample;
        sample.insertion = 1e-4 * k;
        sample.rotation = 0.001 * (k % 37);
        sample.dialUpDown = -0.002 * (k % 11);
        sample.buttons = static_cast<std::uint8_t>(k % 3 == 0 ? procedure::kAir : 0);
        trace.samples.push_back(sample);
    }
    const std::vector<char> encoded = db::encodeStoredTrace(trace);
    db::SessionResult result;
    result.trace = QByteArray(encoded.data(), static_cast<qsizetype>(encoded.size()));
    result.duration = 0.5;
    const qint64 session = records.beginSession(ada, std::nullopt, "navigation-straight", "keyboard");
    records.completeSession(ada, session, result);

    const QByteArray stored = records.sessionTrace(ada, session);
    const procedure::InputTrace back = db::decodeStoredTrace(std::vector<char>(stored.begin(), stored.end()));
    EXPECT_EQ(back, trace);
    EXPECT_EQ(records.sessionTrace(admin, session), stored);
    EXPECT_FALSE(records.sessionCase(ada, session).has_value());
    const qint64 caseId = records.storeCase(ada, "case-7.xml", "<case seed=\"7\"/>");
    const qint64 withCase = records.beginSession(ada, caseId, "navigation-straight", "keyboard");
    EXPECT_EQ(records.sessionCase(ada, withCase).value_or(""), "<case seed=\"7\"/>");

    try {
        (void)records.sessionTrace(ada, session + 100);
        ADD_FAILURE() << "an unknown session was read";
    } catch (const db::DatabaseError& error) {
        EXPECT_NE(std::string(error.what()).find(std::to_string(session + 100)), std::string::npos)
            << error.what();
    }
}

}  // namespace
