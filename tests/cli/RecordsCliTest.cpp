// The records through the command line, as a person or a script uses them:
// first start, users and roles, a stored and scored session, benchmark sets
// with re-scoring, progress, CSV / xAPI / signed PDF reports, verification
// and tampering, backup. Passwords travel in environment variables only.
//
// One database is built once for the suite (SetUpTestSuite): an expert user
// runs the scripted expert twice (1 s of simulated time each, to keep the
// suite short), the administrator derives the "core-navigation" benchmark set
// from those sessions, and student ada runs the scripted novice once.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct Result {
    int status = -1;
    std::string output;
};

/// `env` holds NAME=VALUE words placed before the executable.
Result colonosim(const std::string& env, const std::string& arguments)
{
    const std::string command = "env " + env + " " + COLONOSIM_EXECUTABLE + " " + arguments + " 2>&1";
    Result result;
    FILE* pipe = popen(command.c_str(), "r");
    std::array<char, 4096> buffer{};
    while (pipe != nullptr && fgets(buffer.data(), buffer.size(), pipe) != nullptr) {
        result.output += buffer.data();
    }
    const int raw = pipe != nullptr ? pclose(pipe) : -1;
    result.status = raw >= 0 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return result;
}

std::string read(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

const std::string kAdmin = "COLONOSIM_PASSWORD=admin-secret-1";

class RecordsCli : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_dir =
            std::filesystem::temp_directory_path() / ("colonosim-records-cli-" + std::to_string(::getpid()));
        std::filesystem::create_directories(s_dir);
        s_db = (s_dir / "records.sqlite").string();
        const std::string db = " --db " + s_db;
        auto must = [](const Result& r) { ASSERT_EQ(r.status, 0) << r.output; };
        must(colonosim("COLONOSIM_ADMIN_PASSWORD=admin-secret-1 " + kAdmin +
                           " COLONOSIM_NEW_PASSWORD=expert-secret-1",
                       "user add expert --role student --as admin" + db));
        must(colonosim(kAdmin + " COLONOSIM_NEW_PASSWORD=ada-secret-1",
                       "user add ada --role student --as admin" + db));
        must(colonosim(kAdmin + " COLONOSIM_NEW_PASSWORD=bob-secret-1",
                       "user add bob --role student --as admin" + db));
        for (int n = 0; n < 2; ++n) {
            must(colonosim("COLONOSIM_PASSWORD=expert-secret-1",
                           "run --default --operator expert --max-time 1 --user expert --out " +
                               (s_dir / ("expert" + std::to_string(n))).string() + db));
        }
        must(
            colonosim(kAdmin, "benchmarks derive --name core-navigation --from-user expert --as admin" + db));
        must(colonosim("COLONOSIM_PASSWORD=ada-secret-1",
                       "run --default --operator novice --max-time 1 --user ada "
                       "--json --out " +
                           (s_dir / "ada").string() + db));
    }
    static void TearDownTestSuite() { std::filesystem::remove_all(s_dir); }

    static std::string db() { return " --db " + s_db; }
    static std::string path(const std::string& name) { return (s_dir / name).string(); }

    static std::filesystem::path s_dir;
    static std::string s_db;
};
std::filesystem::path RecordsCli::s_dir;
std::string RecordsCli::s_db;

TEST(RecordsFirstStart, CreatesAnAdministratorWithAPasswordShownOnce)
{
    const auto dir =
        std::filesystem::temp_directory_path() / ("colonosim-first-start-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::vector<std::string> passwords;
    for (const char* name : {"a.sqlite", "b.sqlite"}) {
        const std::string db = " --db " + (dir / name).string();
        const auto first = colonosim("COLONOSIM_PASSWORD=guess-guess", "user list --as admin" + db);
        EXPECT_EQ(first.status, 2) << first.output;  // the guess is wrong
        std::smatch match;
        ASSERT_TRUE(std::regex_search(first.output, match, std::regex("with the password (\\S+)")))
            << first.output;
        passwords.push_back(match[1]);
        const auto second = colonosim("COLONOSIM_PASSWORD=" + passwords.back(), "user list --as admin" + db);
        EXPECT_EQ(second.status, 0) << second.output;
        EXPECT_NE(second.output.find("admin\tadministrator"), std::string::npos) << second.output;
        EXPECT_EQ(second.output.find("with the password"), std::string::npos);  // shown once only
    }
    EXPECT_NE(passwords[0], passwords[1]);  // never a fixed default
    std::filesystem::remove_all(dir);
}

TEST_F(RecordsCli, UsersRolesAndRefusals)
{
    const auto list = colonosim("COLONOSIM_PASSWORD=ada-secret-1", "user list --json --as ada" + db());
    ASSERT_EQ(list.status, 0) << list.output;
    const auto users = nlohmann::json::parse(list.output);
    ASSERT_EQ(users.size(), 1u);  // a student sees only themselves
    EXPECT_EQ(users[0]["name"], "ada");
    const auto add = colonosim("COLONOSIM_PASSWORD=ada-secret-1 COLONOSIM_NEW_PASSWORD=eve-secret-1",
                               "user add eve --role student --as ada" + db());
    EXPECT_EQ(add.status, 2);
    EXPECT_NE(add.output.find("refused: ada (student) may not add users"), std::string::npos) << add.output;
    const auto role = colonosim(kAdmin + " COLONOSIM_NEW_PASSWORD=eve-secret-1",
                                "user add eve --role king --as admin" + db());
    EXPECT_EQ(role.status, 2);
    EXPECT_NE(role.output.find("role \"king\" is not one of student, instructor, administrator"),
              std::string::npos);
    const auto wrong = colonosim("COLONOSIM_PASSWORD=not-adas", "progress --user ada" + db());
    EXPECT_EQ(wrong.status, 2);
    EXPECT_NE(wrong.output.find("authentication failed"), std::string::npos);
    const auto argument = colonosim("", "user list --as ada --password ada-secret-1" + db());
    EXPECT_EQ(argument.status, 2);  // no option takes a password
    const auto other = colonosim("COLONOSIM_PASSWORD=ada-secret-1", "progress --user bob --as ada" + db());
    EXPECT_EQ(other.status, 2);
    EXPECT_NE(other.output.find("a student reads only their own records"), std::string::npos) << other.output;
    const auto task =
        colonosim("COLONOSIM_PASSWORD=ada-secret-1",
                  "run --default --operator novice --task polypectomy --user ada --out " + path("x") + db());
    EXPECT_EQ(task.status, 2);
    EXPECT_NE(task.output.find("--task = polypectomy cannot be run yet"), std::string::npos) << task.output;
}

TEST_F(RecordsCli, PasswordsComeFromFilesAndAChangedOneReplacesTheOld)
{
    const auto secret = [&](const std::string& name, const std::string& text) {
        std::ofstream(path(name)) << text << '\n';  // a trailing newline, as an editor leaves it
        return path(name);
    };
    const auto added = colonosim(kAdmin, "user add zoe --role student --as admin --new-password-file " +
                                             secret("zoe-1", "zoe-secret-1") + db());
    ASSERT_EQ(added.status, 0) << added.output;
    // The acting user's password from a file instead of the environment.
    const auto fromFile =
        colonosim("", "user list --as zoe --password-file " + secret("zoe-as", "zoe-secret-1") + db());
    EXPECT_EQ(fromFile.status, 0) << fromFile.output;
    // A student changes their own password; the old one stops working.
    const auto changed =
        colonosim("COLONOSIM_PASSWORD=zoe-secret-1",
                  "user passwd zoe --as zoe --new-password-file " + secret("zoe-2", "zoe-secret-2") + db());
    ASSERT_EQ(changed.status, 0) << changed.output;
    EXPECT_NE(changed.output.find("password of zoe changed"), std::string::npos) << changed.output;
    const auto old = colonosim("COLONOSIM_PASSWORD=zoe-secret-1", "user list --as zoe" + db());
    EXPECT_EQ(old.status, 2);
    EXPECT_NE(old.output.find("authentication failed"), std::string::npos) << old.output;
    EXPECT_EQ(colonosim("COLONOSIM_PASSWORD=zoe-secret-2", "user list --as zoe" + db()).status, 0);
    // Nobody but an administrator changes another user's password.
    const auto other = colonosim("COLONOSIM_PASSWORD=zoe-secret-2 COLONOSIM_NEW_PASSWORD=taken-over-1",
                                 "user passwd ada --as zoe" + db());
    EXPECT_EQ(other.status, 2);
    EXPECT_NE(other.output.find("refused"), std::string::npos) << other.output;
    EXPECT_EQ(colonosim("COLONOSIM_PASSWORD=ada-secret-1", "user list --as ada" + db()).status, 0);
    const auto reset =
        colonosim(kAdmin + " COLONOSIM_NEW_PASSWORD=zoe-secret-3", "user passwd zoe --as admin" + db());
    EXPECT_EQ(reset.status, 0) << reset.output;
    EXPECT_EQ(colonosim("COLONOSIM_PASSWORD=zoe-secret-3", "user list --as zoe" + db()).status, 0);
    // A password file that does not exist is named.
    const auto missing = colonosim("", "user list --as zoe --password-file " + path("no-such-file") + db());
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.output.find("no-such-file"), std::string::npos) << missing.output;
}

TEST_F(RecordsCli, AnInstructorReadsTheStudentsOfTheirCohortsOnly)
{
    auto must = [](const Result& r) { ASSERT_EQ(r.status, 0) << r.output; };
    must(colonosim(kAdmin + " COLONOSIM_NEW_PASSWORD=teacher-secret-1",
                   "user add teacher --role instructor --as admin" + db()));
    must(colonosim(kAdmin, "user cohort add spring" + db() + " --as admin"));
    must(colonosim(kAdmin, "user cohort member spring ada --as admin" + db()));
    must(colonosim(kAdmin, "user cohort instructor spring teacher --as admin" + db()));
    const auto ada =
        colonosim("COLONOSIM_PASSWORD=teacher-secret-1", "progress --user ada --as teacher" + db());
    EXPECT_EQ(ada.status, 0) << ada.output;
    const auto bob =
        colonosim("COLONOSIM_PASSWORD=teacher-secret-1", "progress --user bob --as teacher" + db());
    EXPECT_EQ(bob.status, 2);
    EXPECT_NE(bob.output.find("an instructor reads only the students of their cohorts"), std::string::npos)
        << bob.output;
    const auto byStudent =
        colonosim("COLONOSIM_PASSWORD=ada-secret-1", "user cohort add autumn --as ada" + db());
    EXPECT_EQ(byStudent.status, 2);
    EXPECT_NE(byStudent.output.find("may not add cohorts"), std::string::npos) << byStudent.output;
    const auto notInstructor = colonosim(kAdmin, "user cohort instructor spring bob --as admin" + db());
    EXPECT_EQ(notInstructor.status, 2);
    EXPECT_NE(notInstructor.output.find("only an instructor can be assigned"), std::string::npos);
}

TEST_F(RecordsCli, SessionsAreStoredScoredAndRescored)
{
    const auto progress = colonosim("COLONOSIM_PASSWORD=ada-secret-1", "progress --user ada --json" + db());
    ASSERT_EQ(progress.status, 0) << progress.output;
    const auto p = nlohmann::json::parse(progress.output);
    EXPECT_EQ(p["completed_sessions"], 1);
    EXPECT_EQ(p["tasks"][0]["id"], "navigation-straight");
    EXPECT_EQ(p["tasks"][0]["state"], "unlocked");
    EXPECT_EQ(p["learning_curve"]["cusum"].size(), 1u);
    bool unavailable = false;
    for (const auto& t : p["tasks"]) {
        unavailable = unavailable || (t["id"] == "polypectomy" && t["state"] == "unavailable");
    }
    EXPECT_TRUE(unavailable);
    EXPECT_EQ(p["certification"].size(), 6u);
    // The expert's sessions were stored before the benchmark set existed and re-scored after.
    const auto csv = colonosim("COLONOSIM_PASSWORD=expert-secret-1",
                               "report --user expert --format csv --out " + path("expert.csv") + db());
    ASSERT_EQ(csv.status, 0) << csv.output;
    std::istringstream rows(read(path("expert.csv")));
    std::string header, row;
    std::getline(rows, header);
    EXPECT_NE(header.find("max_handle_force [N]"), std::string::npos);
    EXPECT_NE(header.find("score:composite"), std::string::npos);
    int n = 0;
    while (std::getline(rows, row)) {
        ++n;
        EXPECT_EQ(std::count(row.begin(), row.end(), ','), std::count(header.begin(), header.end(), ','));
    }
    EXPECT_EQ(n, 2);
    const auto again =
        colonosim(kAdmin, "benchmarks derive --name core-navigation --from-user expert --as admin" + db());
    EXPECT_EQ(again.status, 0) << again.output;
    EXPECT_NE(again.output.find("version 2"), std::string::npos) << again.output;
    EXPECT_NE(again.output.find("3 session(s) re-scored"), std::string::npos) << again.output;
    // Re-scoring changes the stored scores, not only the message: benchmarks drawn
    // from the novice's own session score that session as proficient.
    const auto composite = [&] {
        const auto r = colonosim("COLONOSIM_PASSWORD=ada-secret-1",
                                 "report --user ada --format csv --out " + path("ada.csv") + db());
        EXPECT_EQ(r.status, 0) << r.output;
        std::istringstream lines(read(path("ada.csv")));
        std::string head, last, line;
        std::getline(lines, head);
        while (std::getline(lines, line)) {
            last = line;
        }
        const auto cells = [](const std::string& text) {
            std::vector<std::string> out;
            std::stringstream in(text);
            for (std::string cell; std::getline(in, cell, ',');) {
                out.push_back(cell);
            }
            return out;
        };
        const std::vector<std::string> names = cells(head);
        const std::vector<std::string> values = cells(last);
        const auto at = std::find(names.begin(), names.end(), "score:composite");
        EXPECT_NE(at, names.end()) << head;
        const auto k = static_cast<size_t>(at - names.begin());
        return k < values.size() ? std::stod(values[k]) : std::nan("");
    };
    const auto secondRun =
        colonosim("COLONOSIM_PASSWORD=ada-secret-1",
                  "run --default --operator novice --max-time 1 --user ada --out " + path("ada2") + db());
    ASSERT_EQ(secondRun.status, 0) << secondRun.output;  // two sessions to derive a spread from
    const double before = composite();
    const auto fromNovice =
        colonosim(kAdmin, "benchmarks derive --name core-navigation --from-user ada --as admin" + db());
    ASSERT_EQ(fromNovice.status, 0) << fromNovice.output;
    EXPECT_NE(fromNovice.output.find("version 3"), std::string::npos) << fromNovice.output;
    const double after = composite();
    EXPECT_LT(before, 100.0);
    EXPECT_GT(after, before) << "re-scored against benchmarks from its own values";
}

TEST_F(RecordsCli, XapiStatementsHaveTheStatementStructure)
{
    const auto r = colonosim("COLONOSIM_PASSWORD=ada-secret-1",
                             "report --user ada --format xapi --out " + path("ada.json") + db());
    ASSERT_EQ(r.status, 0) << r.output;
    const auto statements = nlohmann::json::parse(read(path("ada.json")));
    ASSERT_EQ(statements.size(), 1u);
    const auto& s = statements[0];
    const std::regex uuid("[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}");
    const std::regex iri("[a-z][a-z0-9+.-]*://\\S+");
    EXPECT_TRUE(std::regex_match(s["id"].get<std::string>(), uuid));
    EXPECT_EQ(s["actor"]["objectType"], "Agent");
    EXPECT_TRUE(std::regex_match(s["actor"]["account"]["homePage"].get<std::string>(), iri));
    EXPECT_EQ(s["actor"]["account"]["name"], "ada");
    EXPECT_EQ(s["verb"]["id"], "http://adlnet.gov/expapi/verbs/completed");
    EXPECT_TRUE(s["verb"]["display"].contains("en-US"));
    EXPECT_EQ(s["object"]["objectType"], "Activity");
    EXPECT_TRUE(std::regex_match(s["object"]["id"].get<std::string>(), iri));
    const auto& result = s["result"];
    EXPECT_TRUE(result["completion"].get<bool>());
    EXPECT_TRUE(result["success"].is_boolean());
    const double scaled = result["score"]["scaled"];
    EXPECT_GE(scaled, -1.0);
    EXPECT_LE(scaled, 1.0);
    EXPECT_GE(result["score"]["raw"].get<double>(), result["score"]["min"].get<double>());
    EXPECT_LE(result["score"]["raw"].get<double>(), result["score"]["max"].get<double>());
    EXPECT_TRUE(std::regex_match(result["duration"].get<std::string>(), std::regex("PT[0-9]+(\\.[0-9]+)?S")));
    for (const auto& [key, value] : result["extensions"].items()) {
        EXPECT_TRUE(std::regex_match(key, iri)) << key;
    }
    EXPECT_TRUE(result["extensions"].begin()->contains("max_handle_force"));
    EXPECT_TRUE(std::regex_match(s["timestamp"].get<std::string>(),
                                 std::regex("\\d{4}-\\d{2}-\\d{2}T\\d{2}:\\d{2}:\\d{2}(\\.\\d+)?Z")));
}

TEST_F(RecordsCli, TheSignedPdfRendersVerifiesAndFailsWhenTampered)
{
    const auto refused = colonosim("COLONOSIM_PASSWORD=ada-secret-1",
                                   "report --user ada --format pdf --out " + path("self.pdf") + db());
    EXPECT_EQ(refused.status, 2);
    EXPECT_NE(refused.output.find("only administrators"), std::string::npos) << refused.output;
    const auto r =
        colonosim(kAdmin, "report --user ada --format pdf --as admin --out " + path("ada.pdf") + db());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string artefacts = COLONOSIM_TEST_ARTEFACTS;
    std::filesystem::create_directories(artefacts);
    const int rendered = std::system(
        ("pdftoppm -png -r 60 -f 1 -l 1 " + path("ada.pdf") + " " + artefacts + "/report").c_str());
    ASSERT_EQ(rendered, 0);
    const auto png = std::filesystem::path(artefacts) / "report-1.png";
    ASSERT_TRUE(std::filesystem::exists(png));
    EXPECT_GT(std::filesystem::file_size(png), 5000u);
    const auto valid = colonosim("", "report verify " + path("ada.pdf") + db());
    EXPECT_EQ(valid.status, 0) << valid.output;
    EXPECT_NE(valid.output.find("valid: certification report of ada, issued by admin"), std::string::npos);
    // One byte of the content changed.
    std::string bytes = read(path("ada.pdf"));
    const size_t at = bytes.find("/Title");
    ASSERT_NE(at, std::string::npos);
    bytes[at + 1] = 't';
    std::ofstream(path("tampered.pdf"), std::ios::binary) << bytes;
    const auto tampered = colonosim("", "report verify " + path("tampered.pdf") + db());
    EXPECT_EQ(tampered.status, 1);
    EXPECT_NE(tampered.output.find("invalid"), std::string::npos) << tampered.output;
    // Verifying never creates a database: with none at the path it says so.
    const auto missing =
        colonosim("", "report verify " + path("ada.pdf") + " --db " + path("missing.sqlite"));
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.output.find("missing.sqlite: there is no such file"), std::string::npos)
        << missing.output;
    EXPECT_FALSE(std::filesystem::exists(path("missing.sqlite")));
    // A validly signed file that the records do not know (another database) fails too.
    ASSERT_EQ(colonosim("COLONOSIM_ADMIN_PASSWORD=other-secret-1 COLONOSIM_PASSWORD=other-secret-1",
                        "user list --as admin --db " + path("other.sqlite"))
                  .status,
              0);
    const auto elsewhere =
        colonosim("", "report verify " + path("ada.pdf") + " --db " + path("other.sqlite"));
    EXPECT_EQ(elsewhere.status, 1);
    EXPECT_NE(elsewhere.output.find("no matching certificate"), std::string::npos) << elsewhere.output;
}

TEST_F(RecordsCli, BackupIsForAdministratorsAndOpens)
{
    const auto refused =
        colonosim("COLONOSIM_PASSWORD=ada-secret-1", "backup --as ada --out " + path("b0.sqlite") + db());
    EXPECT_EQ(refused.status, 2);
    EXPECT_FALSE(std::filesystem::exists(path("b0.sqlite")));
    const auto r = colonosim(kAdmin, "backup --as admin --out " + path("b1.sqlite") + db());
    ASSERT_EQ(r.status, 0) << r.output;
    const auto list = colonosim(kAdmin, "user list --as admin --db " + path("b1.sqlite"));
    EXPECT_EQ(list.status, 0) << list.output;
    EXPECT_NE(list.output.find("expert"), std::string::npos);
    const auto again = colonosim(kAdmin, "backup --as admin --out " + path("b1.sqlite") + db());
    EXPECT_EQ(again.status, 2);  // never overwrites
}

}  // namespace
