#include "case_generator/RequireExpression.h"

#include "case_generator/CaseNames.h"
#include "case_generator/Quantity.h"
#include "case_generator/Statistics.h"

#include <algorithm>
#include <cctype>

namespace colonosim::cases {

namespace {

struct FlagInfo {
    std::string_view name;
    Stage stage;
};
constexpr FlagInfo kFlags[] = {
    {"hysterectomy", Stage::History},      {"prior_surgery", Stage::History},
    {"anticoagulant", Stage::History},     {"adhesions", Stage::History},
    {"redundant_sigmoid", Stage::Anatomy}, {"redundant_transverse", Stage::Anatomy},
    {"mobile_descending", Stage::Anatomy}, {"mobile_ascending", Stage::Anatomy},
    {"diverticulosis", Stage::Pathology},  {"severe_diverticulosis", Stage::Pathology},
    {"colitis", Stage::Pathology},         {"hemorrhoids", Stage::Pathology},
    {"polypectomy", Stage::Pathology},
};

constexpr std::string_view kLesionPredicates[] = {"lesion",
                                                  "adenoma",
                                                  "advanced_adenoma",
                                                  "cancer",
                                                  "serrated_lesion",
                                                  "sessile_serrated_lesion",
                                                  "hyperplastic_polyp",
                                                  "lipoma",
                                                  "flat_lesion",
                                                  "depressed_lesion",
                                                  "pedunculated_lesion",
                                                  "sessile_lesion",
                                                  "lst"};

struct MetricInfo {
    std::string_view name;
    Stage stage;
};
constexpr MetricInfo kMetrics[] = {
    {"age", Stage::Patient},
    {"bmi", Stage::Patient},
    {"colon_length", Stage::Anatomy},
    {"sigmoid_length", Stage::Anatomy},
    {"transverse_length", Stage::Anatomy},
    {"lesions", Stage::Pathology},
    {"adenomas", Stage::Pathology},
    {"diverticula", Stage::Pathology},
    {"hemorrhoid_grade", Stage::Pathology},
    {"boston", Stage::Environment},
    {"boston_right", Stage::Environment},
    {"boston_transverse", Stage::Environment},
    {"boston_left", Stage::Environment},
    {"difficulty", Stage::Difficulty},
};

std::string knownNames()
{
    std::string out;
    for (const FlagInfo& f : kFlags) {
        out += std::string(f.name) + ", ";
    }
    for (const std::string_view p : kLesionPredicates) {
        out += std::string(p) + "(...), ";
    }
    for (const MetricInfo& m : kMetrics) {
        out += std::string(m.name) + (&m == &kMetrics[std::size(kMetrics) - 1] ? " <op> N" : ", ");
    }
    return out;
}

std::vector<Segment> regionSegments(const std::string& region)
{
    using S = Segment;
    if (region == "right") {
        return {S::Cecum, S::Ascending, S::HepaticFlexure};
    }
    if (region == "left") {
        return {S::SplenicFlexure, S::Descending, S::Sigmoid};
    }
    if (region == "proximal") {
        return {S::Cecum, S::Ascending, S::HepaticFlexure, S::Transverse, S::SplenicFlexure};
    }
    if (region == "distal") {
        return {S::Descending, S::Sigmoid, S::Rectum};
    }
    if (const std::optional<Segment> s = parseName<Segment>(region)) {
        return {*s};
    }
    return {};
}

class Parser {
public:
    explicit Parser(const std::string& text) : m_text(text) {}

    RequireExpression::Terms parseAll()
    {
        RequireExpression::Terms terms;
        skipSpace();
        if (atEnd()) {
            fail("an empty expression");
        }
        for (;;) {
            terms.push_back(term());
            skipSpace();
            if (atEnd()) {
                return terms;
            }
            if (!acceptWord("and")) {
                fail("\"and\" or the end");
            }
        }
    }

private:
    [[noreturn]] void fail(const std::string& expected) const
    {
        throw ExpressionError("--require \"" + m_text + "\": at column " + std::to_string(m_pos + 1) +
                              ": expected " + expected + " (terms: " + knownNames() + ")");
    }

    bool atEnd() const { return m_pos >= m_text.size(); }
    void skipSpace()
    {
        while (!atEnd() && std::isspace(static_cast<unsigned char>(m_text[m_pos]))) {
            ++m_pos;
        }
    }

    std::string word()
    {
        skipSpace();
        const std::size_t start = m_pos;
        while (!atEnd() &&
               (std::isalnum(static_cast<unsigned char>(m_text[m_pos])) || m_text[m_pos] == '_')) {
            if (m_pos == start && std::isdigit(static_cast<unsigned char>(m_text[m_pos]))) {
                break;
            }
            ++m_pos;
        }
        return m_text.substr(start, m_pos - start);
    }

    bool acceptWord(std::string_view expected)
    {
        const std::size_t saved = m_pos;
        if (word() == expected) {
            return true;
        }
        m_pos = saved;
        return false;
    }

    bool accept(std::string_view token)
    {
        skipSpace();
        if (m_text.compare(m_pos, token.size(), token) == 0) {
            m_pos += token.size();
            return true;
        }
        return false;
    }

    double number()
    {
        skipSpace();
        const std::size_t start = m_pos;
        while (!atEnd() &&
               (std::isdigit(static_cast<unsigned char>(m_text[m_pos])) || m_text[m_pos] == '.')) {
            ++m_pos;
        }
        const std::optional<double> value =
            parseNumber(std::string_view(m_text).substr(start, m_pos - start));
        if (!value) {
            m_pos = start;
            fail("a number");
        }
        return *value;
    }

    std::optional<Comparison> comparison()
    {
        if (accept("<=")) {
            return Comparison::LessEqual;
        }
        if (accept(">=")) {
            return Comparison::GreaterEqual;
        }
        if (accept("==") || accept("=")) {
            return Comparison::Equal;
        }
        if (accept("<")) {
            return Comparison::Less;
        }
        if (accept(">")) {
            return Comparison::Greater;
        }
        return std::nullopt;
    }

    int wholeMm()
    {
        const double value = number();
        if (value != static_cast<int>(value) || value > 1000) {
            fail("a whole number of millimetres");
        }
        if (!accept("mm")) {
            fail("\"mm\" after the size");
        }
        return static_cast<int>(value);
    }

    void sizeArgument(RequireTerm& t)
    {
        if (const std::optional<Comparison> op = comparison()) {
            const int mm = wholeMm();
            switch (*op) {
            case Comparison::Less: t.maxSizeMm = mm - 1; break;
            case Comparison::LessEqual: t.maxSizeMm = mm; break;
            case Comparison::Equal: t.minSizeMm = t.maxSizeMm = mm; break;
            case Comparison::GreaterEqual: t.minSizeMm = mm; break;
            case Comparison::Greater: t.minSizeMm = mm + 1; break;
            }
            return;
        }
        const double first = number();
        if (first != static_cast<int>(first)) {
            fail("a whole number of millimetres");
        }
        if (accept("-")) {
            t.minSizeMm = static_cast<int>(first);
            t.maxSizeMm = wholeMm();
        } else {
            if (!accept("mm")) {
                fail("\"mm\" or \"-\" after the size");
            }
            t.minSizeMm = t.maxSizeMm = static_cast<int>(first);
        }
        if (t.minSizeMm > t.maxSizeMm) {
            fail("a size range whose first value is not above its second");
        }
    }

    RequireTerm term()
    {
        RequireTerm t;
        skipSpace();
        t.negated = acceptWord("not");
        const std::size_t start = m_pos;
        t.name = word();
        if (t.name.empty()) {
            fail("a name");
        }
        for (const MetricInfo& m : kMetrics) {
            if (m.name == t.name) {
                t.kind = RequireTerm::Kind::Metric;
                t.stage = m.stage;
                const std::optional<Comparison> op = comparison();
                if (!op) {
                    fail("a comparison (<=, >=, <, >, =) after " + t.name);
                }
                t.op = *op;
                t.value = number();
                if (!accept("mm")) {
                    accept("cm");
                }
                t.text = std::string(m_text, start, m_pos - start);
                t.text.erase(std::remove(t.text.begin(), t.text.end(), ' '), t.text.end());
                return finish(t);
            }
        }
        for (const FlagInfo& f : kFlags) {
            if (f.name == t.name) {
                t.kind = RequireTerm::Kind::Flag;
                t.stage = f.stage;
                t.text = t.name;
                return finish(t);
            }
        }
        if (std::find(std::begin(kLesionPredicates), std::end(kLesionPredicates), t.name) ==
            std::end(kLesionPredicates)) {
            m_pos = start;
            fail("a known term, not \"" + t.name + "\"");
        }
        t.kind = RequireTerm::Kind::LesionPredicate;
        t.stage = Stage::Pathology;
        t.text = t.name;
        if (accept("(")) {
            std::vector<std::string> args;
            do {
                skipSpace();
                const std::size_t argStart = m_pos;
                const char c = atEnd() ? '\0' : m_text[m_pos];
                if (std::isdigit(static_cast<unsigned char>(c)) || c == '<' || c == '>' || c == '=') {
                    sizeArgument(t);
                } else {
                    const std::string region = word();
                    const std::vector<Segment> segments = regionSegments(region);
                    if (segments.empty()) {
                        m_pos = argStart;
                        fail("a size (6-9mm, >=10mm) or a region (right, left, proximal, distal, or a "
                             "segment: " +
                             allowedNames<Segment>() + ")");
                    }
                    t.segments.insert(t.segments.end(), segments.begin(), segments.end());
                }
                args.push_back(std::string(m_text, argStart, m_pos - argStart));
            } while (accept(","));
            if (!accept(")")) {
                fail("\",\" or \")\"");
            }
            t.text += "(";
            for (std::size_t i = 0; i < args.size(); ++i) {
                std::string a = args[i];
                a.erase(std::remove(a.begin(), a.end(), ' '), a.end());
                t.text += (i ? ", " : "") + a;
            }
            t.text += ")";
        }
        return finish(t);
    }

    static RequireTerm finish(RequireTerm t)
    {
        if (t.negated) {
            t.text = "not " + t.text;
        }
        return t;
    }

    const std::string& m_text;
    std::size_t m_pos = 0;
};

bool compare(double a, Comparison op, double b)
{
    switch (op) {
    case Comparison::Less: return a < b;
    case Comparison::LessEqual: return a <= b;
    case Comparison::Equal: return a == b;
    case Comparison::GreaterEqual: return a >= b;
    case Comparison::Greater: return a > b;
    }
    return false;
}

bool lesionKindMatches(const std::string& name, const Lesion& l)
{
    if (name == "lesion") {
        return true;
    }
    if (name == "adenoma") {
        return isAdenoma(l.histology);
    }
    if (name == "advanced_adenoma") {
        return isAdvancedAdenoma(l);
    }
    if (name == "cancer") {
        return l.histology == Histology::Adenocarcinoma;
    }
    if (name == "serrated_lesion") {
        return isSerrated(l.histology);
    }
    if (name == "sessile_serrated_lesion") {
        return l.histology == Histology::SessileSerrated;
    }
    if (name == "hyperplastic_polyp") {
        return l.histology == Histology::Hyperplastic;
    }
    if (name == "lipoma") {
        return l.histology == Histology::Lipoma;
    }
    if (name == "flat_lesion") {
        return l.paris == Paris::IIa || l.paris == Paris::IIb || l.paris == Paris::LstGranular ||
               l.paris == Paris::LstNonGranular;
    }
    if (name == "depressed_lesion") {
        return l.paris == Paris::IIc;
    }
    if (name == "pedunculated_lesion") {
        return l.paris == Paris::Ip;
    }
    if (name == "sessile_lesion") {
        return l.paris == Paris::Is || l.paris == Paris::Isp;
    }
    if (name == "lst") {
        return l.paris == Paris::LstGranular || l.paris == Paris::LstNonGranular;
    }
    return false;
}

bool flagHolds(const std::string& name, const Case& c, const Statistics& stats)
{
    if (name == "hysterectomy") {
        return c.history.hysterectomy;
    }
    if (name == "prior_surgery") {
        return c.history.priorAbdominalSurgery || c.history.hysterectomy;
    }
    if (name == "anticoagulant") {
        return c.history.anticoagulant != Anticoagulant::None;
    }
    if (name == "adhesions") {
        return !c.adhesions.empty();
    }
    if (name == "redundant_sigmoid") {
        return c.anatomy.length[static_cast<int>(Segment::Sigmoid)] >= stats.redundantSigmoid;
    }
    if (name == "redundant_transverse") {
        return c.anatomy.length[static_cast<int>(Segment::Transverse)] >= stats.redundantTransverse;
    }
    if (name == "mobile_descending") {
        return c.anatomy.descendingMobile;
    }
    if (name == "mobile_ascending") {
        return c.anatomy.ascendingMobileFraction > 0.0;
    }
    if (name == "diverticulosis") {
        return !c.diverticula.empty();
    }
    if (name == "severe_diverticulosis") {
        return c.diverticula.size() > 10;
    }
    if (name == "colitis") {
        return c.colitis != ColitisExtent::None;
    }
    if (name == "hemorrhoids") {
        return c.hemorrhoidGrade > 0;
    }
    if (name == "polypectomy") {
        return c.task == TrainingTask::Polypectomy;
    }
    return false;
}

}  // namespace

std::optional<double> metricValue(const std::string& name, const Case& c, const Statistics&)
{
    if (name == "age") {
        return c.patient.age;
    }
    if (name == "bmi") {
        return c.patient.bmi;
    }
    if (name == "colon_length") {
        return quantity::segmentLength.quantise(c.anatomy.colonLength()) * 100.0;
    }
    if (name == "sigmoid_length") {
        return c.anatomy.length[static_cast<int>(Segment::Sigmoid)] * 100.0;
    }
    if (name == "transverse_length") {
        return c.anatomy.length[static_cast<int>(Segment::Transverse)] * 100.0;
    }
    if (name == "lesions") {
        return static_cast<double>(c.lesions.size());
    }
    if (name == "adenomas") {
        return static_cast<double>(std::count_if(c.lesions.begin(), c.lesions.end(),
                                                 [](const Lesion& l) { return isAdenoma(l.histology); }));
    }
    if (name == "diverticula") {
        return static_cast<double>(c.diverticula.size());
    }
    if (name == "hemorrhoid_grade") {
        return c.hemorrhoidGrade;
    }
    if (name == "boston") {
        return c.environment.bostonTotal();
    }
    if (name == "boston_right" || name == "boston_transverse" || name == "boston_left") {
        const std::optional<BowelRegion> region = parseName<BowelRegion>(name.substr(7));
        return c.environment.preparation[static_cast<int>(*region)].boston;
    }
    if (name == "difficulty") {
        return c.difficulty.level;
    }
    return std::nullopt;
}

bool termHolds(const RequireTerm& term, const Case& c, const Statistics& stats)
{
    bool holds = false;
    switch (term.kind) {
    case RequireTerm::Kind::Flag: holds = flagHolds(term.name, c, stats); break;
    case RequireTerm::Kind::Metric: {
        const std::optional<double> value = metricValue(term.name, c, stats);
        holds = value && compare(*value, term.op, term.value);
        break;
    }
    case RequireTerm::Kind::LesionPredicate:
        holds = std::any_of(c.lesions.begin(), c.lesions.end(), [&](const Lesion& l) {
            const double mm = l.size * 1000.0;
            const bool placed = term.segments.empty() || std::find(term.segments.begin(), term.segments.end(),
                                                                   l.place.segment) != term.segments.end();
            return lesionKindMatches(term.name, l) && mm >= term.minSizeMm - 0.5 &&
                   mm <= term.maxSizeMm + 0.5 && placed;
        });
        break;
    }
    return holds != term.negated;
}

RequireExpression RequireExpression::parse(const std::string& text)
{
    RequireExpression expression;
    expression.m_terms = Parser(text).parseAll();
    return expression;
}

bool RequireExpression::holdsAt(Stage stage, const Case& c, const Statistics& stats) const
{
    for (const RequireTerm& term : m_terms) {
        if (term.stage == stage && !termHolds(term, c, stats)) {
            return false;
        }
    }
    return true;
}

std::string RequireExpression::text() const
{
    std::string out;
    for (const RequireTerm& term : m_terms) {
        out += (out.empty() ? "" : " and ") + term.text;
    }
    return out;
}

}  // namespace colonosim::cases
