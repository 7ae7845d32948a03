// Every validation error path: a valid case is changed in one place and the
// reader must refuse it with `file:line: message`, the line holding the
// element at fault and the message naming the field; it never crashes and
// never returns a case.

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseReader.h"
#include "case_generator/CaseWriter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <sstream>

namespace colonosim::cases {

namespace {
/// A woman's case with every kind of element: lesions, diverticula, adhesions.
const Case& validCase()
{
    static const Case c = [] {
        Constraints constraints;
        constraints.sex = Sex::Female;
        constraints.require = RequireExpression::parse("lesions>=2 and diverticula>=2 and hysterectomy");
        return CaseGenerator().generate(11, constraints);
    }();
    return c;
}

std::string lineText(const std::string& text, int line)
{
    std::istringstream in(text);
    std::string current;
    for (int i = 1; std::getline(in, current); ++i) {
        if (i == line) {
            return current;
        }
    }
    return "";
}

/// Reads `text`; expects an error whose message has `expected` and whose line holds `lineContains`.
void expectRefused(const std::string& text, const std::string& expected, const std::string& lineContains)
{
    const ReadResult result = readCase(text, "case.xml");
    EXPECT_FALSE(result.ok());
    ASSERT_FALSE(result.errors.empty());
    bool found = false;
    std::string all;
    for (const std::string& e : result.errors) {
        all += "  " + e + "\n";
        if (!e.starts_with("case.xml:") || e.find(expected) == std::string::npos) {
            continue;
        }
        const int line = std::stoi(e.substr(9));
        found = found || lineText(text, line).find(lineContains) != std::string::npos;
    }
    EXPECT_TRUE(found) << "wanted \"" << expected << "\" on a line with \"" << lineContains << "\"; got:\n"
                       << all;
}
}  // namespace

struct Mutation {
    const char* label;
    const char* from;          ///< first occurrence is replaced
    const char* to;            ///< "=V": replace the value after `from` by V
    const char* expected;      ///< part of the message
    const char* lineContains;  ///< what the reported line holds
};

class Validation : public ::testing::TestWithParam<Mutation> {};

TEST_P(Validation, RefusesWithFileLineAndField)
{
    const Mutation& m = GetParam();
    std::string text = writeCase(validCase());
    const std::size_t at = text.find(m.from);
    ASSERT_NE(at, std::string::npos) << m.from;
    const std::string to = m.to;
    if (to.starts_with('=')) {
        const std::size_t start = at + std::string(m.from).size();
        text.replace(start, text.find('<', start) - start, to.substr(1));
    } else {
        text.replace(at, std::string(m.from).size(), to);
    }
    expectRefused(text, m.expected, m.lineContains);
}

INSTANTIATE_TEST_SUITE_P(
    Table, Validation,
    ::testing::Values(
        Mutation{"malformed", "</patient>", "</patent>", "malformed XML", "<patient>"},
        Mutation{"not_a_case", "<case format_version=\"1\">", "<scene/>\n<case format_version=\"1\">",
                 "must be <case>", "<scene/>"},
        Mutation{"newer_format", "format_version=\"1\"", "format_version=\"2\"", "format_version 2 is newer",
                 "<case"},
        Mutation{"bad_format", "format_version=\"1\"", "format_version=\"one\"", "format_version = \"one\"",
                 "<case"},
        Mutation{"unknown_element", "<indication>", "<mood>calm</mood><indication>",
                 "case: unknown element <mood>", "<mood>"},
        Mutation{"unknown_attribute", "<patient>", "<patient id=\"7\">", "patient: unknown attribute id",
                 "<patient"},
        Mutation{"missing_field", "<hysterectomy>true</hysterectomy>", "", "history: missing <hysterectomy>",
                 "<history>"},
        Mutation{"repeated_field", "<sex>F</sex>", "<sex>F</sex>\n<sex>F</sex>", "<sex> appears twice",
                 "<sex>"},
        Mutation{"missing_unit", "<age unit=\"year\">", "<age>", "patient.age: missing unit attribute",
                 "<age>"},
        Mutation{"wrong_unit", "<height unit=\"cm\">", "<height unit=\"m\">",
                 "patient.height: unit = \"m\", expected \"cm\"", "<height"},
        Mutation{"out_of_range", "<age unit=\"year\">", "=1", "patient.age = 1 year is outside [18, 110]",
                 "<age"},
        Mutation{"nan", "<bmi unit=\"kg/m^2\">", "=nan", "patient.bmi = \"nan\" is not a finite decimal",
                 "<bmi"},
        Mutation{"infinite", "<wall_thickness unit=\"mm\">", "=inf", "tissue.wall_thickness = \"inf\"",
                 "<wall_thickness"},
        Mutation{"exponent", "<insufflation_compliance unit=\"1\">", "=1e0", "is not a finite decimal number",
                 "<insufflation_compliance"},
        Mutation{"text_for_number", "<residual_fluid unit=\"mL\">", "=lots", "residual_fluid = \"lots\"",
                 "<residual_fluid"},
        Mutation{"declared_range", "<wall_young_modulus unit=\"MPa\">", "=25.000",
                 "tissue.wall_young_modulus = 25.000 MPa is outside [0.500, 20.000]", "<wall_young_modulus"},
        Mutation{"segment_range", "<length unit=\"cm\">", "=9.0", "anatomy.segment[rectum].length = 9.0",
                 "<length"},
        Mutation{"whole_number", "<boston unit=\"1\">", "=1.5", "environment.preparation[right].boston = 1.5",
                 "<boston"},
        Mutation{"bad_name", "<sex>F</sex>", "<sex>X</sex>", "patient.sex = \"X\" is not one of: F, M",
                 "<sex>"},
        Mutation{"bad_paris", "<paris>", "=0-III", "pathology.lesion[1].paris = \"0-III\" is not one of",
                 "<paris>"},
        Mutation{"empty_name", "<given_name>", "=", "patient.given_name is empty", "<given_name"},
        Mutation{"bad_segment_attribute", "<segment name=\"cecum\">", "<segment name=\"caecum\">",
                 "name = \"caecum\" is not one of", "caecum"},
        Mutation{"missing_segment", "<segment name=\"cecum\">", "<segment>", "missing attribute name",
                 "<segment>"},
        Mutation{"value_with_element", "<miss_rate unit=\"1\">", "<miss_rate unit=\"1\"><b/>",
                 "unknown element <b> inside a value", "<miss_rate"},
        Mutation{"hysterectomy_man", "<sex>F</sex>", "<sex>M</sex>", "hysterectomy = true for a male patient",
                 "<hysterectomy>"},
        Mutation{"bmi_mismatch", "<weight unit=\"kg\">", "=200.0", "does not match weight / height^2",
                 "<bmi"},
        Mutation{"bad_flag", "<descending_mobile>", "=yes",
                 "anatomy.descending_mobile = \"yes\" is not one of", "<descending_mobile>"},
        Mutation{"bad_seed", "<seed>", "=-3", "provenance.seed = \"-3\" is not a whole number", "<seed>"},
        Mutation{"diverticulum_in_rectum", "<diverticulum>\n            <segment>", "=rectum",
                 "diverticula do not form in the rectum", "rectum"}),
    [](const ::testing::TestParamInfo<Mutation>& info) { return std::string(info.param.label); });

struct PlaceFault {
    const char* label;
    std::function<void(Case&)> change;
    const char* expected;
    const char* lineContains;
};

class ImpossiblePlaces : public ::testing::TestWithParam<PlaceFault> {};

TEST_P(ImpossiblePlaces, AreRefused)
{
    Case c = validCase();
    GetParam().change(c);
    expectRefused(writeCase(c), GetParam().expected, GetParam().lineContains);
}

INSTANTIATE_TEST_SUITE_P(
    Table, ImpossiblePlaces,
    ::testing::Values(
        PlaceFault{"lesion_beyond_its_segment",
                   [](Case& c) {
                       c.lesions[0].place.position =
                           c.anatomy.length[static_cast<int>(c.lesions[0].place.segment)] + 0.01;
                   },
                   "pathology.lesion[1].position", "<position"},
        PlaceFault{"lesion_wider_than_the_lumen",
                   [](Case& c) {
                       c.lesions[1].size = 0.1;
                       c.anatomy.diameter[static_cast<int>(c.lesions[1].place.segment)] = 0.03;
                   },
                   "pathology.lesion[2].size = 100 mm is larger than the lumen's circumference", "<size"},
        PlaceFault{"adhesion_beyond_its_segment",
                   [](Case& c) {
                       c.adhesions[0].place.position =
                           c.anatomy.length[static_cast<int>(c.adhesions[0].place.segment)] + 0.005;
                   },
                   "adhesions.adhesion[1].position", "<position"},
        PlaceFault{"diverticulum_beyond_its_segment",
                   [](Case& c) { c.diverticula[1].place.position = 0.699; },
                   "pathology.diverticulum[2].position", "<position"}),
    [](const ::testing::TestParamInfo<PlaceFault>& info) { return std::string(info.param.label); });

TEST(Validation, AMissingSectionIsNamed)
{
    std::string text = writeCase(validCase());
    const std::size_t start = text.find("<tissue>");
    const std::size_t end = text.find("</tissue>") + 9;
    text.erase(start, end - start);
    expectRefused(text, "case: missing <tissue>", "<case");
}

TEST(Validation, ManyErrorsAreAllReported)
{
    std::string text = writeCase(validCase());
    text.replace(text.find("<height unit=\"cm\">"), 18, "<height unit=\"m\">");
    text.replace(text.find("<sex>F</sex>"), 12, "<sex>X</sex>");
    const ReadResult result = readCase(text, "case.xml");
    EXPECT_FALSE(result.ok());
    EXPECT_GE(result.errors.size(), 2u);
}

TEST(Validation, AMissingFileIsAnError)
{
    const ReadResult result = readCaseFile("/nonexistent/case.xml");
    ASSERT_EQ(result.errors.size(), 1u);
    EXPECT_NE(result.errors[0].find("/nonexistent/case.xml:0: cannot open"), std::string::npos);
}

TEST(Validation, TheValidCaseReadsBack)
{
    const ReadResult result = readCase(writeCase(validCase()), "case.xml");
    ASSERT_TRUE(result.ok()) << (result.errors.empty() ? "" : result.errors.front());
    EXPECT_EQ(*result.value, validCase());
}

TEST(Validation, GarbageNeverCrashes)
{
    for (const std::string text :
         {"", "<", "<case/>", "<case format_version=\"1\"/>", "\0\0\0", "<?xml?><a><b>"}) {
        const ReadResult result = readCase(text, "x.xml");
        EXPECT_FALSE(result.ok());
        EXPECT_FALSE(result.errors.empty());
    }
}

}  // namespace colonosim::cases
