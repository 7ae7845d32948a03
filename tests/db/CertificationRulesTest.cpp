// Certification rule sets of record: the shipped set is version 1 and active,
// an import is validated and stored as a new inactive version, activation
// switches the one active set, every import and activation is audited, and
// the rows are of record (the schema refuses to change or delete them).
#include "db/CertificationRules.h"
#include "curricula/Certification.h"
#include "db/Database.h"
#include "db/Statement.h"
#include "tests/db/TempDir.h"

#include <gtest/gtest.h>

namespace {

using namespace colonosim;

/// The core rule set renamed and renumbered, with 150 procedures required instead of 200.
std::string revised(int version)
{
    std::string xml = curricula::coreRuleSetXml();
    xml.replace(xml.find("name=\"colonoscopy-simulated\" version=\"1\""), 40,
                "name=\"colonoscopy-revised\" version=\"" + std::to_string(version) + "\"");
    xml.replace(xml.find("value=\"200\""), 11, "value=\"150\"");
    return xml;
}

std::vector<std::string> auditOfRuleSets(db::Records& records, const db::Actor& admin)
{
    std::vector<std::string> out;
    for (const db::AuditRow& row : records.audit(admin)) {
        if (row.table == "certification_rule_sets") {
            out.push_back(row.actor + ": " + row.detail);
        }
    }
    return out;
}

class CertificationRulesTest : public ::testing::Test {
protected:
    test::TempDir m_dir;
    db::Database m_database{m_dir / "records.sqlite"};
    db::Records m_records{m_database};
    db::CertificationRules m_rules{m_database};
    db::Actor m_admin = m_records.bootstrapAdministrator("root", "root-password");
};

TEST_F(CertificationRulesTest, TheShippedSetIsVersionOneAndActive)
{
    const db::ActiveRuleSet active = m_rules.active(m_admin);
    EXPECT_EQ(active.stored.name, "colonoscopy-simulated");
    EXPECT_EQ(active.stored.version, 1);
    EXPECT_TRUE(active.stored.importedBy.empty());
    EXPECT_EQ(active.rules.rules.size(), 6U);
    EXPECT_EQ(m_rules.xml(m_admin, 1), curricula::coreRuleSetXml());
    EXPECT_EQ(auditOfRuleSets(m_records, m_admin),
              std::vector<std::string>{"(system): imported colonoscopy-simulated version 1 (active)"});
}

TEST_F(CertificationRulesTest, ImportThenActivateSwitchesTheActiveSetAndIsAudited)
{
    const db::RuleSetVersion stored = m_rules.import(m_admin, revised(2), "revised.xml");
    EXPECT_EQ(stored.version, 2);
    EXPECT_EQ(stored.name, "colonoscopy-revised");
    EXPECT_EQ(stored.importedBy, "root");
    EXPECT_FALSE(stored.active);
    EXPECT_EQ(m_rules.active(m_admin).stored.version, 1);  // imported, not yet active

    m_rules.activate(m_admin, 2);
    const db::ActiveRuleSet active = m_rules.active(m_admin);
    EXPECT_EQ(active.stored.version, 2);
    EXPECT_EQ(active.rules.rules.front().value, 150.0);
    EXPECT_EQ(m_rules.xml(m_admin, 2), revised(2));
    const auto versions = m_rules.versions(m_admin);
    ASSERT_EQ(versions.size(), 2U);
    EXPECT_FALSE(versions[0].active);
    EXPECT_TRUE(versions[1].active);

    m_rules.activate(m_admin, 1);  // back to the shipped set
    EXPECT_EQ(m_rules.active(m_admin).stored.version, 1);
    EXPECT_EQ(auditOfRuleSets(m_records, m_admin),
              (std::vector<std::string>{"(system): imported colonoscopy-simulated version 1 (active)",
                                        "root: imported colonoscopy-revised version 2",
                                        "root: activated colonoscopy-revised version 2",
                                        "root: activated colonoscopy-simulated version 1"}));
}

TEST_F(CertificationRulesTest, AnInvalidFileIsRefusedWithItsLineAndField)
{
    std::string bad = revised(2);
    bad.replace(bad.find("kind=\"none_in_last\""), 19, "kind=\"never\"");
    try {
        (void)m_rules.import(m_admin, bad, "bad.xml");
        FAIL() << "imported an invalid rule set";
    } catch (const db::RuleSetRejected& error) {
        ASSERT_EQ(error.errors().size(), 1U);
        EXPECT_EQ(error.errors()[0].rfind("bad.xml:25: kind = \"never\" is not one of", 0), 0U)
            << error.errors()[0];
    }
    EXPECT_EQ(m_rules.versions(m_admin).size(), 1U);
}

TEST_F(CertificationRulesTest, AVersionNotAboveTheStoredOnesIsRefused)
{
    (void)m_rules.import(m_admin, revised(3), "three.xml");
    for (const int version : {1, 3, 2}) {
        try {
            (void)m_rules.import(m_admin, revised(version), "again.xml");
            FAIL() << "version " << version << " imported twice or out of order";
        } catch (const db::RuleSetRejected& error) {
            ASSERT_EQ(error.errors().size(), 1U);
            EXPECT_EQ(error.errors()[0],
                      "again.xml:11: <certification> version = " + std::to_string(version) +
                          " is already taken or older: a new rule set needs a version of "
                          "at least 4");
        }
    }
    EXPECT_EQ(m_rules.versions(m_admin).size(), 2U);
}

TEST_F(CertificationRulesTest, ActivatingAVersionNotStoredIsRefusedNamingTheStoredOnes)
{
    (void)m_rules.import(m_admin, revised(3), "three.xml");
    try {
        m_rules.activate(m_admin, 2);
        FAIL() << "activated a version that is not stored";
    } catch (const db::DatabaseError& error) {
        EXPECT_STREQ(error.what(),
                     "certification rule set version 2 is not stored: the stored versions are 1, 3");
    }
    EXPECT_EQ(m_rules.active(m_admin).stored.version, 1);
}

TEST_F(CertificationRulesTest, StoredRowsAreOfRecord)
{
    QSqlDatabase c = m_database.connection();
    EXPECT_THROW(db::runStatement(c, QStringLiteral("UPDATE certification_rule_sets SET xml = 'x'")),
                 db::DatabaseError);
    EXPECT_THROW(db::runStatement(c, QStringLiteral("DELETE FROM certification_rule_sets")),
                 db::DatabaseError);
    EXPECT_THROW(
        db::runStatement(c, QStringLiteral("INSERT INTO certification_rule_sets (name, version, xml, "
                                           "active) VALUES ('x', 9, 'x', 1)")),
        db::DatabaseError);  // a second active set
    EXPECT_EQ(m_rules.xml(m_admin, 1), curricula::coreRuleSetXml());
}

}  // namespace
