/// \file
/// `colonosim case generate|validate|stats`: randomized patient cases from
/// population statistics (case_generator/), their validation, and the rates
/// self-check. Format and constraint grammar: docs/case-format.md.

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseNames.h"
#include "case_generator/CaseReader.h"
#include "case_generator/CaseWriter.h"
#include "case_generator/Quantity.h"
#include "case_generator/RateCheck.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/ColonLayout.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace colonosim::cli {

namespace {

using namespace colonosim::cases;

const std::vector<std::string> kConstraintOptions{"--sex",     "--age-min", "--age-max",    "--bmi-min",
                                                  "--bmi-max", "--require", "--difficulty", "--statistics"};

void printHelp()
{
    std::cout << "usage: colonosim case generate --seed N [CONSTRAINTS] --out FILE\n"
                 "       colonosim case validate FILE...\n"
                 "       colonosim case stats [--n N] [--seed N] [CONSTRAINTS] [--json]\n"
                 "Randomized patient cases drawn from population statistics, stored as XML\n"
                 "(docs/case-format.md, schema case_generator/schema/case.xsd).\n"
                 "  generate   writes the case for seed N (0 to 2^64-1); the same seed, constraints and\n"
                 "             versions give the same file, byte for byte\n"
                 "  validate   checks case files; prints file:line: message for every problem\n"
                 "  stats      generates N cases (default 100000) and prints each rate realised next to\n"
                 "             the rate of the statistics file and its source; --json: a list of\n"
                 "             {\"name\", \"source\", \"expected\", \"realised\", \"trials\", \"z\"}\n"
                 "CONSTRAINTS:\n"
                 "  --sex F|M  --age-min A  --age-max B (years, 18-110)  --bmi-min X  --bmi-max X (kg/m^2, "
                 "10-100)\n"
                 "  --difficulty A-B (1 <= A <= B <= 5)\n"
                 "  --require EXPR   e.g. \"flat_lesion(6-9mm, right) and boston<=5 and redundant_sigmoid\"\n"
                 "  --statistics FILE   another statistics file instead of the built-in one\n";
}

std::uint64_t parseSeed(const std::string& option, const std::string& text)
{
    std::uint64_t value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size()) {
        throw UsageError(option + " = " + text +
                         " is not a whole number in the allowed range [0, 18446744073709551615]");
    }
    return value;
}

int wholeNumber(const CommandLine& line, const std::string& option, double min, double max,
                const std::string& unit)
{
    const double value = line.number(option, min, min, max, unit);
    if (value != std::floor(value)) {
        throw UsageError(option + " = " + *line.value(option) +
                         " is not a whole number in the allowed range [" + formatFixed(min, 0) + ", " +
                         formatFixed(max, 0) + "] " + unit);
    }
    return static_cast<int>(value);
}

Constraints parseConstraints(const CommandLine& line)
{
    Constraints c;
    if (const std::optional<std::string> sex = line.value("--sex")) {
        c.sex = parseName<Sex>(*sex);
        if (!c.sex) {
            throw UsageError("--sex = " + *sex + " is not one of: F, M");
        }
    }
    if (line.value("--age-min")) {
        c.ageMin = wholeNumber(line, "--age-min", 18, 110, "years");
    }
    if (line.value("--age-max")) {
        c.ageMax = wholeNumber(line, "--age-max", 18, 110, "years");
    }
    if (line.value("--bmi-min")) {
        c.bmiMin = line.number("--bmi-min", 0, 10, 100, "kg/m^2");
    }
    if (line.value("--bmi-max")) {
        c.bmiMax = line.number("--bmi-max", 0, 10, 100, "kg/m^2");
    }
    if (const std::optional<std::string> range = line.value("--difficulty")) {
        const std::size_t dash = range->find('-');
        const auto digit = [](const std::string& s) { return s.size() == 1 && s[0] >= '1' && s[0] <= '5'; };
        const std::string a = range->substr(0, dash);
        const std::string b = dash == std::string::npos ? a : range->substr(dash + 1);
        if (!digit(a) || !digit(b) || a > b) {
            throw UsageError("--difficulty = " + *range + " is not a range A-B with 1 <= A <= B <= 5");
        }
        c.difficultyMin = a[0] - '0';
        c.difficultyMax = b[0] - '0';
    }
    if (const std::optional<std::string> expression = line.value("--require")) {
        try {
            c.require = RequireExpression::parse(*expression);
        } catch (const ExpressionError& error) {
            throw UsageError(error.what());
        }
    }
    return c;
}

/// The built-in statistics, or those of --statistics FILE.
const Statistics& statisticsFor(const CommandLine& line, Statistics& storage)
{
    const std::optional<std::string> path = line.value("--statistics");
    if (!path) {
        return Statistics::builtIn();
    }
    std::ifstream in(*path, std::ios::binary);
    if (!in) {
        throw UsageError("--statistics = " + *path + ": cannot open the file");
    }
    std::ostringstream text;
    text << in.rdbuf();
    try {
        storage = Statistics::fromJson(text.str(), *path);
    } catch (const StatisticsError& error) {
        throw UsageError(error.what());
    }
    return storage;
}

/// A note when the case's colon, laid out, passes through itself (about one
/// generated case in 20: the lengths are drawn independently, and a long
/// transverse colon can sag through the sigmoid's loop); empty otherwise.
/// The simulator takes such an overlap as the lumen's rest state
/// (physics/LumenSelfContact.h), so the two parts are joined where they
/// overlap. Laying out costs about 5 ms, so the generator does not reject
/// them (52,000 cases/s).
std::string selfOverlapNote(const Case& c)
{
    const geometry::LumenSelfOverlap overlap =
        geometry::lumenSelfOverlap(geometry::layoutColon(toScene(c).anatomy, 0.005).centreline);
    if (overlap.pairs == 0) {
        return {};
    }
    return "note: the colon passes through itself: the lumen at " + formatFixed(overlap.arcA, 3) +
           " m and at " + formatFixed(overlap.arcB, 3) + " m along it overlap by " +
           formatFixed(overlap.deepest * 1e3, 1) +
           " mm; the simulator keeps that overlap as the colon's rest state\n";
}

/// A note when the case's cecum is out of the simulated scope's reach
/// (cases::cecumOutOfReach); empty otherwise.
std::string reachNote(const Case& c)
{
    const std::optional<std::string> reason = cecumOutOfReach(c);
    return reason ? "note: " + *reason + "\n" : std::string();
}

int generate(std::span<char* const> args)
{
    std::vector<std::string> options = kConstraintOptions;
    options.insert(options.end(), {"--seed", "--out"});
    const CommandLine line(args, {"--help"}, options);
    if (line.has("--help")) {
        printHelp();
        return 0;
    }
    if (!line.positional().empty()) {
        throw UsageError("case generate takes no arguments, got " + line.positional().front());
    }
    const std::optional<std::string> seedText = line.value("--seed");
    const std::optional<std::string> out = line.value("--out");
    if (!seedText || !out) {
        throw UsageError("case generate needs --seed N and --out FILE");
    }
    const std::uint64_t seed = parseSeed("--seed", *seedText);
    Statistics storage;
    const Statistics& stats = statisticsFor(line, storage);
    const Constraints constraints = parseConstraints(line);
    const Case c = CaseGenerator(stats).generate(seed, constraints);
    if (*out == "-") {
        std::cout << writeCase(c);
        return 0;
    }
    writeCaseFile(c, *out);
    std::cout << "wrote " << *out << ": " << c.patient.givenName << " " << c.patient.familyName << ", "
              << nameOf(c.patient.sex) << ", " << c.patient.age << " years, BMI "
              << formatFixed(c.patient.bmi, 1) << " kg/m^2, lesions " << c.lesions.size() << ", difficulty "
              << c.difficulty.level << ", task " << nameOf(c.task) << " (seed " << seed << ", attempt "
              << c.provenance.attempt << ")\n"
              << selfOverlapNote(c) << reachNote(c);
    return 0;
}

int validate(std::span<char* const> args)
{
    const CommandLine line(args, {"--help"}, {});
    if (line.has("--help")) {
        printHelp();
        return 0;
    }
    if (line.positional().empty()) {
        throw UsageError("case validate needs at least one FILE");
    }
    int status = 0;
    for (const std::string& path : line.positional()) {
        const ReadResult result = readCaseFile(path);
        if (result.ok()) {
            std::cout << path << ": valid\n" << selfOverlapNote(*result.value) << reachNote(*result.value);
            continue;
        }
        status = 2;
        for (const std::string& error : result.errors) {
            std::cerr << error << '\n';
        }
    }
    return status;
}

int stats(std::span<char* const> args)
{
    std::vector<std::string> options = kConstraintOptions;
    options.insert(options.end(), {"--n", "--seed"});
    const CommandLine line(args, {"--json", "--help"}, options);
    if (line.has("--help")) {
        printHelp();
        return 0;
    }
    if (!line.positional().empty()) {
        throw UsageError("case stats takes no arguments, got " + line.positional().front());
    }
    const int n = wholeNumber(line, "--n", 1, 1e7, "cases");
    const int count = line.value("--n") ? n : 100000;
    const std::uint64_t seed = line.value("--seed") ? parseSeed("--seed", *line.value("--seed")) : 1;
    Statistics storage;
    const Statistics& statistics = statisticsFor(line, storage);
    const Constraints constraints = parseConstraints(line);
    const std::vector<RateEntry> entries =
        checkRates(CaseGenerator(statistics), static_cast<std::uint64_t>(count), seed, constraints);
    if (line.has("--json")) {
        nlohmann::json list = nlohmann::json::array();
        for (const RateEntry& e : entries) {
            list.push_back({{"name", e.name},
                            {"source", e.source},
                            {"expected", e.expected},
                            {"realised", e.realised},
                            {"trials", e.trials},
                            {"z", e.z()}});
        }
        std::cout << list.dump(2) << '\n';
        return 0;
    }
    std::cout << count << " cases from seed " << seed
              << (constraints.empty() ? "" : ", " + constraints.text()) << "; statistics "
              << statistics.version << ", generator " << kGeneratorVersion << "\n";
    if (constraints.bmiMin || constraints.bmiMax || constraints.difficultyMin ||
        !constraints.require.empty()) {
        std::cout << "(expected values account for the sex and age constraints only)\n";
    }
    std::cout << std::left << std::setw(38) << "rate" << std::right << std::setw(10) << "expected"
              << std::setw(10) << "realised" << std::setw(9) << "z" << std::setw(9) << "over"
              << "  source\n";
    for (const RateEntry& e : entries) {
        const int decimals = e.mean ? 2 : 4;
        std::cout << std::left << std::setw(38) << e.name << std::right << std::setw(10)
                  << formatFixed(e.expected, decimals) << std::setw(10) << formatFixed(e.realised, decimals)
                  << std::setw(9) << formatFixed(e.z(), 2) << std::setw(9) << e.trials << "  "
                  << e.source.substr(0, 100) << (e.source.size() > 100 ? "..." : "") << '\n';
    }
    return 0;
}

}  // namespace

int runCase(std::span<char* const> args)
{
    const std::string action = args.empty() ? "--help" : args.front();
    const std::span<char* const> rest = args.empty() ? args : args.subspan(1);
    try {
        if (action == "--help" || action == "-h" || action == "help") {
            printHelp();
            return 0;
        }
        if (action == "generate") {
            return generate(rest);
        }
        if (action == "validate") {
            return validate(rest);
        }
        if (action == "stats") {
            return stats(rest);
        }
    } catch (const ImpossibleConstraints& error) {
        std::cerr << "colonosim case " << action << ": " << error.what() << '\n';
        return 2;
    }
    throw UsageError("unknown action \"" + action + "\" (one of: generate, validate, stats)");
}

}  // namespace colonosim::cli
