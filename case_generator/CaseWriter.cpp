#include "case_generator/CaseWriter.h"

#include "case_generator/CaseNames.h"
#include "case_generator/Quantity.h"

#include <tinyxml2.h>

#include <fstream>
#include <stdexcept>

namespace colonosim::cases {

namespace {

class Writer {
public:
    Writer() : m_printer(nullptr, false) {}

    void open(const char* name) { m_printer.OpenElement(name, false); }
    void close() { m_printer.CloseElement(false); }
    void attribute(const char* name, std::string_view value)
    {
        m_printer.PushAttribute(name, std::string(value).c_str());
    }

    void text(const char* name, std::string_view value)
    {
        open(name);
        m_printer.PushText(std::string(value).c_str());
        close();
    }
    void flag(const char* name, bool value) { text(name, value ? "true" : "false"); }
    void number(const Quantity& q, double si)
    {
        const std::string element(q.element);
        open(element.c_str());
        attribute("unit", q.unit);
        m_printer.PushText(q.format(si).c_str());
        close();
    }
    void place(const WallPlace& p)
    {
        text("segment", nameOf(p.segment));
        number(quantity::position, p.position);
        number(quantity::clockAngle, p.clockAngle);
    }

    tinyxml2::XMLPrinter& printer() { return m_printer; }

private:
    tinyxml2::XMLPrinter m_printer;
};

void writePatient(Writer& w, const Case& c)
{
    const Patient& p = c.patient;
    w.open("patient");
    w.text("given_name", p.givenName);
    w.text("family_name", p.familyName);
    w.text("sex", nameOf(p.sex));
    w.number(quantity::age, p.age);
    w.number(quantity::height, p.height);
    w.number(quantity::weight, p.weight);
    w.number(quantity::bmi, p.bmi);
    w.close();
    w.text("indication", nameOf(c.indication));
    w.open("history");
    w.flag("prior_abdominal_surgery", c.history.priorAbdominalSurgery);
    w.flag("hysterectomy", c.history.hysterectomy);
    w.text("anticoagulant", nameOf(c.history.anticoagulant));
    w.close();
}

void writeAnatomy(Writer& w, const Case& c)
{
    const CaseAnatomy& a = c.anatomy;
    w.open("anatomy");
    for (int i = 0; i < geometry::kNumSegments; ++i) {
        w.open("segment");
        w.attribute("name", nameOf(static_cast<Segment>(i)));
        w.number(quantity::segmentLength, a.length[i]);
        w.number(quantity::segmentDiameter, a.diameter[i]);
        w.close();
    }
    w.number(quantity::ascendingMobileFraction, a.ascendingMobileFraction);
    w.flag("descending_mobile", a.descendingMobile);
    w.number(quantity::transverseMesenteryHeight, a.transverseMesenteryHeight);
    w.number(quantity::sigmoidMesenteryHeight, a.sigmoidMesenteryHeight);
    w.number(quantity::mobileColonMesenteryHeight, a.mobileColonMesenteryHeight);
    w.close();
    const CaseTissue& t = c.tissue;
    w.open("tissue");
    w.number(quantity::wallYoungModulus, t.wallYoungModulus);
    w.number(quantity::wallThickness, t.wallThickness);
    w.number(quantity::mesenteryModulus, t.mesenteryModulus);
    w.number(quantity::mesenteryThickness, t.mesenteryThickness);
    w.number(quantity::adhesionStiffness, t.adhesionStiffness);
    w.number(quantity::surroundingDampingRate, t.surroundingDampingRate);
    w.close();
}

void writePathology(Writer& w, const Case& c)
{
    w.open("pathology");
    for (const Lesion& l : c.lesions) {
        w.open("lesion");
        w.place(l.place);
        w.number(quantity::lesionSize, l.size);
        w.text("paris", nameOf(l.paris));
        w.text("histology", nameOf(l.histology));
        w.number(quantity::lesionStiffness, l.stiffness);
        w.text("colour", nameOf(l.colour));
        w.text("surface", nameOf(l.surface));
        w.number(quantity::niceType, l.niceType);
        w.number(quantity::missRate, l.missRate);
        w.close();
    }
    for (const Diverticulum& d : c.diverticula) {
        w.open("diverticulum");
        w.place(d.place);
        w.number(quantity::diverticulumDiameter, d.diameter);
        w.close();
    }
    w.text("colitis", nameOf(c.colitis));
    w.number(quantity::hemorrhoidGrade, c.hemorrhoidGrade);
    w.close();
    w.open("adhesions");
    for (const Adhesion& a : c.adhesions) {
        w.open("adhesion");
        w.place(a.place);
        w.close();
    }
    w.close();
}

void writeEnvironment(Writer& w, const Case& c)
{
    const Environment& e = c.environment;
    w.open("environment");
    for (int r = 0; r < kNumBowelRegions; ++r) {
        const Preparation& p = e.preparation[r];
        w.open("preparation");
        w.attribute("region", nameOf(static_cast<BowelRegion>(r)));
        w.number(quantity::boston, p.boston);
        w.number(quantity::residualStool, p.residualStool);
        w.number(quantity::residualFluid, p.residualFluid);
        w.close();
    }
    w.number(quantity::insufflationPressure, e.insufflationPressure);
    w.number(quantity::insufflationCompliance, e.insufflationCompliance);
    w.close();
    w.open("difficulty");
    w.number(quantity::difficultyLevel, c.difficulty.level);
    for (const DifficultyFactor& f : c.difficulty.factors) {
        w.open("factor");
        w.attribute("name", f.name);
        w.number(quantity::difficultyPoints, f.points);
        w.close();
    }
    w.close();
    w.text("task", nameOf(c.task));
}

}  // namespace

std::string writeCase(const Case& c)
{
    Writer w;
    w.printer().PushHeader(false, true);
    w.printer().PushComment(
        " colonosim patient case: docs/case-format.md, schema case_generator/schema/case.xsd ");
    w.open("case");
    w.attribute("format_version", std::to_string(c.provenance.formatVersion));
    w.open("provenance");
    w.text("seed", std::to_string(c.provenance.seed));
    w.text("attempt", std::to_string(c.provenance.attempt));
    w.text("generator_version", c.provenance.generatorVersion);
    w.text("statistics_version", c.provenance.statisticsVersion);
    w.text("constraints", c.provenance.constraints);
    w.close();
    writePatient(w, c);
    writeAnatomy(w, c);
    writePathology(w, c);
    writeEnvironment(w, c);
    w.close();
    return std::string(w.printer().CStr(), static_cast<std::size_t>(w.printer().CStrSize() - 1));
}

void writeCaseFile(const Case& c, const std::string& path)
{
    const std::string text = writeCase(c);
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        throw std::runtime_error(path + ": cannot write the case file");
    }
}

}  // namespace colonosim::cases
