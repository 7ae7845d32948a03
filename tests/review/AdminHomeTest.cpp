// The administrator's home screen, driven as a person would: add a user and a
// cohort, reset a password (the user then logs in with it), import a broken
// curriculum (the message names the line) and a good one, read the rule
// status, export a trainee's signed PDF and a cohort's CSV with progress,
// cancel a cohort export (nothing is left), import a broken certification
// rule set (the line named) and a good one, activate it and see the version
// change, and take a backup that opens with its integrity intact.
#include "trainer_ui/review/AdminHome.h"
#include "curricula/Certification.h"
#include "curricula/Curriculum.h"
#include "db/CertificationRules.h"
#include "tests/review/ReviewRecords.h"
#include "tests/review/Screenshot.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSqlQuery>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTableView>
#include <QTest>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace {

using namespace colonosim;

template <class T>
T* child(QWidget& root, const char* name)
{
    T* found = root.findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
}

void choose(QComboBox* box, const QString& text)
{
    const int k = box->findText(text, Qt::MatchStartsWith);
    ASSERT_GE(k, 0) << text.toStdString();
    box->setCurrentIndex(k);
}

void type(QLineEdit* edit, const QString& text)
{
    edit->clear();
    QTest::keyClicks(edit, text);
}

std::string read(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

struct Admin : ::testing::Test {
    test::ReviewRecords& data = test::ReviewRecords::instance();
    app::AppContext context{*data.database, *data.records, data.admin, data.dir};
    app::AdminHome home{context};
    QTabWidget* tabs = nullptr;

    void SetUp() override
    {
        home.resize(1400, 900);
        home.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&home));
        tabs = child<QTabWidget>(home, "adminTabs");
    }
    void open(int tab, const char* shot)
    {
        tabs->setCurrentIndex(tab);
        QApplication::processEvents();
        test::screenshot(home, QString::fromLatin1(shot));
    }
    QString status(const char* name) { return child<QLabel>(home, name)->text(); }
    /// Presses Export and waits for the job to end; the status line then.
    QString exportNow()
    {
        auto* button = child<QPushButton>(home, "exportButton");
        QTest::mouseClick(button, Qt::LeftButton);
        EXPECT_TRUE(QTest::qWaitFor([&] { return button->isEnabled(); }, 60000)) << "the export ends";
        return status("exportStatus");
    }
};

TEST_F(Admin, AddsAUserAndACohortAndResetsAPassword)
{
    tabs->setCurrentIndex(0);
    type(child<QLineEdit>(home, "newUserName"), QStringLiteral("carol"));
    choose(child<QComboBox>(home, "newUserRole"), QStringLiteral("student"));
    type(child<QLineEdit>(home, "newUserPassword"), QStringLiteral("short"));
    QTest::mouseClick(child<QPushButton>(home, "addUserButton"), Qt::LeftButton);
    EXPECT_TRUE(status("usersStatus").contains(QStringLiteral("password length 5 is out of range")))
        << status("usersStatus").toStdString();
    EXPECT_EQ(child<QLineEdit>(home, "newUserName")->text(), QStringLiteral("carol"))
        << "a refused form keeps what was typed";

    type(child<QLineEdit>(home, "newUserPassword"), QStringLiteral("carol-password"));
    QTest::mouseClick(child<QPushButton>(home, "addUserButton"), Qt::LeftButton);
    EXPECT_TRUE(status("usersStatus").contains(QStringLiteral("carol (student) was added")))
        << status("usersStatus").toStdString();
    const auto* users = child<QTableView>(home, "userTable")->model();
    bool listed = false;
    for (int r = 0; r < users->rowCount(); ++r) {
        listed = listed || users->index(r, 0).data().toString() == QStringLiteral("carol");
    }
    EXPECT_TRUE(listed);

    type(child<QLineEdit>(home, "newCohortName"), QStringLiteral("B"));
    QTest::mouseClick(child<QPushButton>(home, "addCohortButton"), Qt::LeftButton);
    choose(child<QComboBox>(home, "memberUser"), QStringLiteral("carol"));
    choose(child<QComboBox>(home, "memberCohort"), QStringLiteral("B"));
    QTest::mouseClick(child<QPushButton>(home, "addToCohortButton"), Qt::LeftButton);
    EXPECT_TRUE(status("usersStatus").contains(QStringLiteral("carol is now in cohort B")))
        << status("usersStatus").toStdString();

    choose(child<QComboBox>(home, "resetUser"), QStringLiteral("carol"));
    type(child<QLineEdit>(home, "resetPassword"), QStringLiteral("carol-new-password"));
    QTest::mouseClick(child<QPushButton>(home, "resetPasswordButton"), Qt::LeftButton);
    open(0, "admin-1-users");
    EXPECT_NO_THROW((void)data.records->authenticate("carol", "carol-new-password"));
    EXPECT_THROW((void)data.records->authenticate("carol", "carol-password"), db::AuthenticationFailed);
}

TEST_F(Admin, ImportsCurriculaAndNamesTheLineOfAnError)
{
    std::string broken = curricula::coreCurriculumXml();
    const std::string limit = "max_time_s=\"600\"";
    ASSERT_NE(broken.find(limit), std::string::npos);
    // The line the first task's time limit is on, counted from 1.
    const auto line = 1 + std::count(broken.begin(),
                                     broken.begin() + static_cast<std::ptrdiff_t>(broken.find(limit)), '\n');
    broken.replace(broken.find(limit), limit.size(), "max_time_s=\"-5\"");
    const auto brokenFile = data.dir / "broken-curriculum.xml";
    std::ofstream(brokenFile) << broken;
    type(child<QLineEdit>(home, "curriculumPath"), QString::fromStdString(brokenFile.string()));
    QTest::mouseClick(child<QPushButton>(home, "importCurriculumButton"), Qt::LeftButton);
    auto* messages = child<QListWidget>(home, "curriculumMessages");
    ASSERT_GE(messages->count(), 1);
    EXPECT_TRUE(messages->item(0)->text().startsWith(QStringLiteral("Line %1: ").arg(line)))
        << messages->item(0)->text().toStdString();
    EXPECT_TRUE(status("curriculumStatus").contains(QStringLiteral("was not imported")));
    open(1, "admin-2-curriculum-error");

    const auto goodFile = data.dir / "good-curriculum.xml";
    std::ofstream(goodFile) << curricula::coreCurriculumXml();
    type(child<QLineEdit>(home, "curriculumPath"), QString::fromStdString(goodFile.string()));
    QTest::mouseClick(child<QPushButton>(home, "importCurriculumButton"), Qt::LeftButton);
    EXPECT_TRUE(status("curriculumStatus").startsWith(QStringLiteral("Imported curriculum colonoscopy-core")))
        << status("curriculumStatus").toStdString();
    open(1, "admin-2-curriculum");
    EXPECT_EQ(data.records->curriculum(data.admin, "colonoscopy-core"), curricula::coreCurriculumXml());
}

TEST_F(Admin, SeesRuleStatusAndExportsReports)
{
    tabs->setCurrentIndex(2);
    choose(child<QComboBox>(home, "certTrainee"), QStringLiteral("ada"));
    const auto* rules = child<QTableView>(home, "ruleTable")->model();
    ASSERT_GE(rules->rowCount(), 1);
    EXPECT_TRUE(rules->index(0, 0).data().toString().endsWith(QStringLiteral("met")));
    EXPECT_TRUE(status("ruleSummary").contains(QStringLiteral("ada: 4 completed session(s)")))
        << status("ruleSummary").toStdString();

    // One trainee, signed PDF.
    choose(child<QComboBox>(home, "exportScope"), QStringLiteral("trainee ada"));
    choose(child<QComboBox>(home, "exportFormat"), QStringLiteral("PDF"));
    const auto pdf = data.dir / "ada.pdf";
    type(child<QLineEdit>(home, "exportPath"), QString::fromStdString(pdf.string()));
    EXPECT_TRUE(exportNow().startsWith(QStringLiteral("Written:"))) << status("exportStatus").toStdString();
    EXPECT_EQ(read(pdf).substr(0, 5), "%PDF-");
    EXPECT_NE(read(pdf).find("%COLONOSIM-SIGNATURE v1 user=ada"), std::string::npos);

    // The cohort as CSV, with progress: one row per session of ada and bob.
    choose(child<QComboBox>(home, "exportScope"), QStringLiteral("cohort A"));
    choose(child<QComboBox>(home, "exportFormat"), QStringLiteral("CSV"));
    const auto csv = data.dir / "cohort-A.csv";
    type(child<QLineEdit>(home, "exportPath"), QString::fromStdString(csv.string()));
    EXPECT_TRUE(exportNow().startsWith(QStringLiteral("Written:"))) << status("exportStatus").toStdString();
    EXPECT_EQ(child<QProgressBar>(home, "exportProgress")->value(), 2);
    EXPECT_EQ(child<QProgressBar>(home, "exportProgress")->maximum(), 2);
    std::istringstream lines(read(csv));
    int rows = -1;
    for (std::string line; std::getline(lines, line);) {
        ++rows;
    }
    EXPECT_EQ(rows, static_cast<int>(data.adaSessions.size() + data.bobSessions.size()));
    open(2, "admin-3-certification");

    // A cancelled cohort export leaves nothing behind.
    choose(child<QComboBox>(home, "exportFormat"), QStringLiteral("PDF"));
    const auto folder = data.dir / "cohort-A-certificates";
    type(child<QLineEdit>(home, "exportPath"), QString::fromStdString(folder.string()));
    auto* button = child<QPushButton>(home, "exportButton");
    QTest::mouseClick(button, Qt::LeftButton);
    QTest::mouseClick(child<QPushButton>(home, "cancelExportButton"), Qt::LeftButton);
    ASSERT_TRUE(QTest::qWaitFor([&] { return button->isEnabled(); }, 60000)) << "the export ends";
    EXPECT_TRUE(status("exportStatus").contains(QStringLiteral("cancelled; no file was written")))
        << status("exportStatus").toStdString();
    EXPECT_FALSE(std::filesystem::exists(folder));
    EXPECT_FALSE(std::filesystem::exists(folder.string() + ".partial"));
}

TEST_F(Admin, ImportsAndActivatesACertificationRuleSet)
{
    tabs->setCurrentIndex(2);
    choose(child<QComboBox>(home, "certTrainee"), QStringLiteral("ada"));
    EXPECT_TRUE(status("activeRuleSet").startsWith(QStringLiteral("colonoscopy-simulated, version 1")))
        << status("activeRuleSet").toStdString();

    // A file with a kind that does not exist: nothing stored, the line named.
    std::string revised = curricula::coreRuleSetXml();
    const auto swap = [&revised](const std::string& from, const std::string& to) {
        ASSERT_NE(revised.find(from), std::string::npos) << from;
        revised.replace(revised.find(from), from.size(), to);
    };
    swap("name=\"colonoscopy-simulated\" version=\"1\"", "name=\"colonoscopy-revised\" version=\"2\"");
    swap("value=\"200\"", "value=\"150\"");
    swap("at least 200 simulated procedures", "at least 150 simulated procedures");
    swap("JAG provisional certification: at least 200 procedures",
         "local revision of the JAG provisional certification: 150 procedures");
    std::string broken = revised;
    broken.replace(broken.find("kind=\"none_in_last\""), 19, "kind=\"never\"");
    const auto brokenFile = data.dir / "broken-rules.xml";
    std::ofstream(brokenFile) << broken;
    type(child<QLineEdit>(home, "ruleSetPath"), QString::fromStdString(brokenFile.string()));
    QTest::mouseClick(child<QPushButton>(home, "importRuleSetButton"), Qt::LeftButton);
    auto* problems = child<QListWidget>(home, "ruleSetProblems");
    ASSERT_EQ(problems->count(), 1);
    EXPECT_TRUE(
        problems->item(0)->text().startsWith(QStringLiteral("Line 25: kind = \"never\" is not one of")))
        << problems->item(0)->text().toStdString();
    EXPECT_TRUE(status("ruleSetStatus").contains(QStringLiteral("was not imported: 1 problem(s) to fix.")));
    open(2, "admin-3-certification-rules-error");

    // The revised set: imported as version 2, not active until activated.
    const auto goodFile = data.dir / "revised-rules.xml";
    std::ofstream(goodFile) << revised;
    type(child<QLineEdit>(home, "ruleSetPath"), QString::fromStdString(goodFile.string()));
    QTest::mouseClick(child<QPushButton>(home, "importRuleSetButton"), Qt::LeftButton);
    EXPECT_TRUE(status("ruleSetStatus").startsWith(QStringLiteral("Imported colonoscopy-revised, version 2")))
        << status("ruleSetStatus").toStdString();
    EXPECT_FALSE(problems->isVisible());
    EXPECT_TRUE(status("activeRuleSet").startsWith(QStringLiteral("colonoscopy-simulated, version 1")));
    choose(child<QComboBox>(home, "ruleSetVersions"), QStringLiteral("colonoscopy-revised, version 2"));
    QTest::mouseClick(child<QPushButton>(home, "activateRuleSetButton"), Qt::LeftButton);
    EXPECT_TRUE(
        status("activeRuleSet").startsWith(QStringLiteral("colonoscopy-revised, version 2 (imported by")))
        << status("activeRuleSet").toStdString();
    EXPECT_TRUE(status("ruleSummary").endsWith(QStringLiteral("(rule set colonoscopy-revised, version 2).")))
        << status("ruleSummary").toStdString();
    const auto* rules = child<QTableView>(home, "ruleTable")->model();
    ASSERT_GE(rules->rowCount(), 1);
    EXPECT_EQ(rules->index(0, 1).data().toString(), QStringLiteral("at least 150 simulated procedures"));
    open(2, "admin-3-certification-rules");

    // Back to the shipped set, so the suite's other tests see the records they expect.
    db::CertificationRules(*data.database).activate(data.admin, 1);
}

TEST_F(Admin, TakesABackupThatOpensIntact)
{
    const auto backup = data.dir / "backup.sqlite";
    type(child<QLineEdit>(home, "backupPath"), QString::fromStdString(backup.string()));
    QTest::mouseClick(child<QPushButton>(home, "backupButton"), Qt::LeftButton);
    open(3, "admin-4-backup");
    ASSERT_TRUE(status("backupStatus").startsWith(QStringLiteral("Backed up to")))
        << status("backupStatus").toStdString();
    db::Database copy(backup);
    QSqlQuery check(copy.connection());
    ASSERT_TRUE(check.exec(QStringLiteral("PRAGMA integrity_check")) && check.next());
    EXPECT_EQ(check.value(0).toString(), QStringLiteral("ok"));
    db::Records records(copy);
    EXPECT_EQ(records.sessions(data.admin, "ada").size(), data.adaSessions.size());

    QTest::mouseClick(child<QPushButton>(home, "backupButton"), Qt::LeftButton);
    EXPECT_TRUE(status("backupStatus").contains(QStringLiteral("exists already")))
        << "a backup never overwrites";
}

}  // namespace
