#include "case_generator/CaseReader.h"

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseNames.h"
#include "case_generator/ElementReader.h"
#include "case_generator/Quantity.h"
#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/physics/TissueParameters.h"

#include <tinyxml2.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace colonosim::cases {

namespace {

using geometry::AnatomyParameters;
using physics::TissueParameters;
using tinyxml2::XMLElement;

void readProvenance(ElementReader& r, const XMLElement* root, Case& c)
{
    const XMLElement* e = r.section(root, "provenance", "case");
    if (e == nullptr) {
        return;
    }
    r.allowOnly(e, "provenance",
                {"seed", "attempt", "generator_version", "statistics_version", "constraints"});
    c.provenance.seed = r.whole(e, "seed", "provenance").value_or(0);
    c.provenance.attempt = r.whole(e, "attempt", "provenance").value_or(0);
    c.provenance.generatorVersion = r.text(e, "generator_version", "provenance").value_or("");
    c.provenance.statisticsVersion = r.text(e, "statistics_version", "provenance").value_or("");
    c.provenance.constraints = r.text(e, "constraints", "provenance", true).value_or("");
}

void readPatient(ElementReader& r, const XMLElement* root, Case& c)
{
    if (const XMLElement* e = r.section(root, "patient", "case")) {
        r.allowOnly(e, "patient", {"given_name", "family_name", "sex", "age", "height", "weight", "bmi"});
        Patient& p = c.patient;
        p.givenName = r.text(e, "given_name", "patient").value_or("");
        p.familyName = r.text(e, "family_name", "patient").value_or("");
        p.sex = r.name<Sex>(e, "sex", "patient").value_or(Sex::Female);
        p.age = static_cast<int>(r.number(e, quantity::age, "patient", true).value_or(0));
        p.height = r.number(e, quantity::height, "patient").value_or(0);
        p.weight = r.number(e, quantity::weight, "patient").value_or(0);
        const std::optional<double> bmi = r.number(e, quantity::bmi, "patient");
        p.bmi = bmi.value_or(0);
        if (bmi && p.height > 0 && std::abs(p.bmi - p.weight / (p.height * p.height)) > 0.15) {
            r.error(e->FirstChildElement("bmi"),
                    "patient.bmi = " + formatFixed(p.bmi, 1) + " kg/m^2 does not match weight / height^2 = " +
                        formatFixed(p.weight / (p.height * p.height), 1) + " kg/m^2");
        }
    }
    c.indication = r.name<Indication>(root, "indication", "case").value_or(Indication::Screening);
    if (const XMLElement* e = r.section(root, "history", "case")) {
        r.allowOnly(e, "history", {"prior_abdominal_surgery", "hysterectomy", "anticoagulant"});
        c.history.priorAbdominalSurgery = r.flag(e, "prior_abdominal_surgery", "history").value_or(false);
        const std::optional<bool> hysterectomy = r.flag(e, "hysterectomy", "history");
        c.history.hysterectomy = hysterectomy.value_or(false);
        if (hysterectomy == true && c.patient.sex == Sex::Male) {
            r.error(e->FirstChildElement("hysterectomy"), "history.hysterectomy = true for a male patient");
        }
        c.history.anticoagulant =
            r.name<Anticoagulant>(e, "anticoagulant", "history").value_or(Anticoagulant::None);
    }
}

void readAnatomy(ElementReader& r, const XMLElement* root, Case& c)
{
    if (const XMLElement* e = r.section(root, "anatomy", "case")) {
        r.allowOnly(e, "anatomy",
                    {"segment", "ascending_mobile_fraction", "descending_mobile",
                     "transverse_mesentery_height", "sigmoid_mesentery_height",
                     "mobile_colon_mesentery_height"});
        std::array<bool, geometry::kNumSegments> seen{};
        for (const XMLElement* s = e->FirstChildElement("segment"); s != nullptr;
             s = s->NextSiblingElement("segment")) {
            r.allowAttributes(s, "anatomy.segment", {"name"});
            r.allowOnly(s, "anatomy.segment", {"length", "diameter"});
            const std::optional<Segment> segment = r.nameAttribute<Segment>(s, "name", "anatomy.segment");
            if (!segment) {
                continue;
            }
            const int i = static_cast<int>(*segment);
            const std::string path = "anatomy.segment[" + std::string(nameOf(*segment)) + "]";
            if (seen[i]) {
                r.error(s, path + " appears twice");
            }
            seen[i] = true;
            const auto fields = AnatomyParameters::fields();
            c.anatomy.length[i] =
                r.number(s, quantity::segmentLength.withRangeOf(*fields[i].spec), path).value_or(0);
            c.anatomy.diameter[i] =
                r.number(s, quantity::segmentDiameter.withRangeOf(*fields[geometry::kNumSegments + i].spec),
                         path)
                    .value_or(0);
        }
        for (int i = 0; i < geometry::kNumSegments; ++i) {
            if (!seen[i]) {
                r.error(e, "anatomy: missing <segment name=\"" +
                               std::string(nameOf(static_cast<Segment>(i))) + "\">");
            }
        }
        CaseAnatomy& a = c.anatomy;
        a.ascendingMobileFraction = r.number(e, quantity::ascendingMobileFraction, "anatomy").value_or(0);
        a.descendingMobile = r.flag(e, "descending_mobile", "anatomy").value_or(false);
        a.transverseMesenteryHeight = r.number(e,
                                               quantity::transverseMesenteryHeight.withRangeOf(
                                                   AnatomyParameters::transverseMesenteryHeightSpec),
                                               "anatomy")
                                          .value_or(0);
        a.sigmoidMesenteryHeight = r.number(e,
                                            quantity::sigmoidMesenteryHeight.withRangeOf(
                                                AnatomyParameters::sigmoidMesenteryHeightSpec),
                                            "anatomy")
                                       .value_or(0);
        a.mobileColonMesenteryHeight = r.number(e,
                                                quantity::mobileColonMesenteryHeight.withRangeOf(
                                                    AnatomyParameters::mobileColonMesenteryHeightSpec),
                                                "anatomy")
                                           .value_or(0);
    }
    if (const XMLElement* e = r.section(root, "tissue", "case")) {
        r.allowOnly(e, "tissue",
                    {"wall_young_modulus", "wall_thickness", "mesentery_modulus", "mesentery_thickness",
                     "adhesion_stiffness", "surrounding_damping_rate"});
        CaseTissue& t = c.tissue;
        t.wallYoungModulus =
            r.number(e, quantity::wallYoungModulus.withRangeOf(TissueParameters::youngModulusSpec), "tissue")
                .value_or(0);
        t.wallThickness =
            r.number(e, quantity::wallThickness.withRangeOf(TissueParameters::thicknessSpec), "tissue")
                .value_or(0);
        t.mesenteryModulus =
            r.number(e, quantity::mesenteryModulus.withRangeOf(TissueParameters::mesenteryModulusSpec),
                     "tissue")
                .value_or(0);
        t.mesenteryThickness =
            r.number(e, quantity::mesenteryThickness.withRangeOf(TissueParameters::mesenteryThicknessSpec),
                     "tissue")
                .value_or(0);
        t.adhesionStiffness =
            r.number(e, quantity::adhesionStiffness.withRangeOf(TissueParameters::adhesionSpec), "tissue")
                .value_or(0);
        t.surroundingDampingRate =
            r.number(e,
                     quantity::surroundingDampingRate.withRangeOf(TissueParameters::surroundingDampingSpec),
                     "tissue")
                .value_or(0);
    }
}

/// Reads segment, position and clock angle, and checks the place exists.
WallPlace readPlace(ElementReader& r, const XMLElement* e, const std::string& path, const Case& c)
{
    WallPlace p;
    const std::optional<Segment> segment = r.name<Segment>(e, "segment", path);
    p.segment = segment.value_or(Segment::Rectum);
    const std::optional<double> position = r.number(e, quantity::position, path);
    p.position = position.value_or(0);
    p.clockAngle = r.number(e, quantity::clockAngle, path, true).value_or(0);
    if (segment && position) {
        const double length = c.anatomy.length[static_cast<int>(*segment)];
        if (length > 0 && p.position > length + 1e-9) {
            r.error(e->FirstChildElement("position"),
                    path + ".position = " + quantity::position.format(p.position) +
                        " cm lies beyond the end of the " + std::string(nameOf(*segment)) + ", which is " +
                        quantity::segmentLength.format(length) + " cm long");
        }
    }
    return p;
}

void readPathology(ElementReader& r, const XMLElement* root, Case& c)
{
    if (const XMLElement* e = r.section(root, "pathology", "case")) {
        r.allowOnly(e, "pathology", {"lesion", "diverticulum", "colitis", "hemorrhoid_grade"});
        int index = 0;
        for (const XMLElement* l = e->FirstChildElement("lesion"); l != nullptr;
             l = l->NextSiblingElement("lesion")) {
            const std::string path = "pathology.lesion[" + std::to_string(++index) + "]";
            r.allowOnly(l, path,
                        {"segment", "position", "clock_angle", "size", "paris", "histology", "stiffness",
                         "colour", "surface", "nice_type", "miss_rate"});
            Lesion lesion;
            lesion.place = readPlace(r, l, path, c);
            const std::optional<double> size = r.number(l, quantity::lesionSize, path, true);
            lesion.size = size.value_or(0);
            const double diameter = c.anatomy.diameter[static_cast<int>(lesion.place.segment)];
            if (size && diameter > 0 && lesion.size > std::numbers::pi * diameter + 1e-9) {
                r.error(l->FirstChildElement("size"),
                        path + ".size = " + quantity::lesionSize.format(lesion.size) +
                            " mm is larger than the lumen's circumference there (" +
                            formatFixed(std::numbers::pi * diameter * 1000.0, 0) + " mm)");
            }
            lesion.paris = r.name<Paris>(l, "paris", path).value_or(Paris::Is);
            lesion.histology = r.name<Histology>(l, "histology", path).value_or(Histology::TubularLowGrade);
            lesion.stiffness = r.number(l, quantity::lesionStiffness, path).value_or(0);
            lesion.colour = r.name<Colour>(l, "colour", path).value_or(Colour::Isochromatic);
            lesion.surface = r.name<Surface>(l, "surface", path).value_or(Surface::Smooth);
            lesion.niceType = static_cast<int>(r.number(l, quantity::niceType, path, true).value_or(1));
            lesion.missRate = r.number(l, quantity::missRate, path).value_or(0);
            c.lesions.push_back(lesion);
        }
        index = 0;
        for (const XMLElement* d = e->FirstChildElement("diverticulum"); d != nullptr;
             d = d->NextSiblingElement("diverticulum")) {
            const std::string path = "pathology.diverticulum[" + std::to_string(++index) + "]";
            r.allowOnly(d, path, {"segment", "position", "clock_angle", "diameter"});
            Diverticulum diverticulum;
            diverticulum.place = readPlace(r, d, path, c);
            const XMLElement* segment = d->FirstChildElement("segment");
            if (segment != nullptr && segment->GetText() != nullptr &&
                std::string_view(segment->GetText()) == "rectum") {
                r.error(segment, path + ".segment = rectum: diverticula do not form in the rectum");
            }
            diverticulum.diameter = r.number(d, quantity::diverticulumDiameter, path).value_or(0);
            c.diverticula.push_back(diverticulum);
        }
        c.colitis = r.name<ColitisExtent>(e, "colitis", "pathology").value_or(ColitisExtent::None);
        c.hemorrhoidGrade =
            static_cast<int>(r.number(e, quantity::hemorrhoidGrade, "pathology", true).value_or(0));
    }
    if (const XMLElement* e = r.section(root, "adhesions", "case")) {
        r.allowOnly(e, "adhesions", {"adhesion"});
        int index = 0;
        for (const XMLElement* a = e->FirstChildElement("adhesion"); a != nullptr;
             a = a->NextSiblingElement("adhesion")) {
            const std::string path = "adhesions.adhesion[" + std::to_string(++index) + "]";
            r.allowOnly(a, path, {"segment", "position", "clock_angle"});
            c.adhesions.push_back({readPlace(r, a, path, c)});
        }
    }
}

void readEnvironment(ElementReader& r, const XMLElement* root, Case& c)
{
    if (const XMLElement* e = r.section(root, "environment", "case")) {
        r.allowOnly(e, "environment", {"preparation", "insufflation_pressure", "insufflation_compliance"});
        std::array<bool, kNumBowelRegions> seen{};
        for (const XMLElement* p = e->FirstChildElement("preparation"); p != nullptr;
             p = p->NextSiblingElement("preparation")) {
            r.allowAttributes(p, "environment.preparation", {"region"});
            r.allowOnly(p, "environment.preparation", {"boston", "residual_stool", "residual_fluid"});
            const std::optional<BowelRegion> region =
                r.nameAttribute<BowelRegion>(p, "region", "environment.preparation");
            if (!region) {
                continue;
            }
            const int i = static_cast<int>(*region);
            const std::string path = "environment.preparation[" + std::string(nameOf(*region)) + "]";
            if (seen[i]) {
                r.error(p, path + " appears twice");
            }
            seen[i] = true;
            Preparation& prep = c.environment.preparation[i];
            prep.boston = static_cast<int>(r.number(p, quantity::boston, path, true).value_or(0));
            prep.residualStool = r.number(p, quantity::residualStool, path).value_or(0);
            prep.residualFluid = r.number(p, quantity::residualFluid, path).value_or(0);
        }
        for (int i = 0; i < kNumBowelRegions; ++i) {
            if (!seen[i]) {
                r.error(e, "environment: missing <preparation region=\"" +
                               std::string(nameOf(static_cast<BowelRegion>(i))) + "\">");
            }
        }
        c.environment.insufflationPressure =
            r.number(e,
                     quantity::insufflationPressure.withRangeOf(physics::EnvironmentParameters::pressureSpec),
                     "environment")
                .value_or(0);
        c.environment.insufflationCompliance =
            r.number(e, quantity::insufflationCompliance, "environment").value_or(1);
    }
    if (const XMLElement* e = r.section(root, "difficulty", "case")) {
        r.allowOnly(e, "difficulty", {"level", "factor"});
        c.difficulty.level =
            static_cast<int>(r.number(e, quantity::difficultyLevel, "difficulty", true).value_or(1));
        for (const XMLElement* f = e->FirstChildElement("factor"); f != nullptr;
             f = f->NextSiblingElement("factor")) {
            r.allowAttributes(f, "difficulty.factor", {"name"});
            r.allowOnly(f, "difficulty.factor", {"points"});
            const char* name = f->Attribute("name");
            if (name == nullptr || *name == '\0') {
                r.error(f, "difficulty.factor: missing attribute name");
            }
            c.difficulty.factors.push_back(
                {name != nullptr ? name : "",
                 r.number(f, quantity::difficultyPoints, "difficulty.factor").value_or(0)});
        }
    }
    c.task = r.name<TrainingTask>(root, "task", "case").value_or(TrainingTask::Intubation);
}

}  // namespace

ReadResult readCase(std::string_view text, const std::string& fileName)
{
    ReadResult result;
    tinyxml2::XMLDocument document;
    if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
        const char* detail = document.ErrorStr();
        result.errors.push_back(fileName + ":" + std::to_string(document.ErrorLineNum()) +
                                ": malformed XML: " + (detail != nullptr ? detail : "unknown error"));
        return result;
    }
    ElementReader r(fileName, result.errors);
    const XMLElement* root = document.RootElement();
    if (root == nullptr || std::string_view(root->Name()) != "case") {
        r.error(root, "the root element must be <case>, not <" +
                          std::string(root != nullptr ? root->Name() : "") + ">");
        return result;
    }
    r.allowAttributes(root, "case", {"format_version"});
    const char* version = root->Attribute("format_version");
    const std::optional<double> parsed = version != nullptr ? parseNumber(version) : std::nullopt;
    if (!parsed || *parsed != std::floor(*parsed) || *parsed < 1) {
        r.error(root, "case: format_version = \"" + std::string(version != nullptr ? version : "") +
                          "\" is missing or not a whole number >= 1");
        return result;
    }
    if (*parsed > kFormatVersion) {
        r.error(root, "case: format_version " + formatFixed(*parsed, 0) +
                          " is newer than this program reads (" + std::to_string(kFormatVersion) +
                          "); use a newer colonosim");
        return result;
    }
    r.allowOnly(root, "case",
                {"provenance", "patient", "indication", "history", "anatomy", "tissue", "pathology",
                 "adhesions", "environment", "difficulty", "task"});
    Case c;
    c.provenance.formatVersion = static_cast<int>(*parsed);
    readProvenance(r, root, c);
    readPatient(r, root, c);
    readAnatomy(r, root, c);
    readPathology(r, root, c);
    readEnvironment(r, root, c);
    if (result.errors.empty()) {
        result.value = std::move(c);
    }
    return result;
}

ReadResult readCaseFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        ReadResult result;
        result.errors.push_back(path + ":0: cannot open the case file");
        return result;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return readCase(text.str(), path);
}

}  // namespace colonosim::cases
