#pragma once
/// \file
/// One patient case: the patient, indication, history, anatomy, tissue,
/// pathology, environment and difficulty. Values are SI inside the code
/// (m, kg, Pa, m^3, rad); the case file writes clinical units and says so in
/// each value's unit attribute (docs/case-format.md). The XML file is the case
/// of record: every number here is already rounded to the precision the file
/// writes, so reading a written case gives back an equal Case.

#include "simcore/geometry/Segment.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace colonosim::cases {

using geometry::Segment;

enum class Sex : std::uint8_t { Female, Male };
enum class Indication : std::uint8_t { Screening, PositiveStoolTest, Surveillance, Symptoms };
enum class Anticoagulant : std::uint8_t { None, Antiplatelet, VitaminKAntagonist, Doac };
enum class Histology : std::uint8_t {
    TubularLowGrade,
    TubularHighGrade,
    Tubulovillous,
    Villous,
    Hyperplastic,
    SessileSerrated,
    TraditionalSerrated,
    Adenocarcinoma,
    Lipoma,
};
/// Paris classification (0-I.. superficial, 1 and 2 advanced), and the
/// laterally spreading tumours (flat lesions >= 10 mm), granular or not.
enum class Paris : std::uint8_t { Ip, Isp, Is, IIa, IIb, IIc, LstGranular, LstNonGranular, Type1, Type2 };
enum class Colour : std::uint8_t { Pale, Isochromatic, Reddish, Yellowish };
enum class Surface : std::uint8_t { Smooth, Granular, Lobulated, Ulcerated };
enum class ColitisExtent : std::uint8_t { None, Proctitis, LeftSided, Extensive };
/// The Boston Bowel Preparation Scale scores three regions.
enum class BowelRegion : std::uint8_t { Right, Transverse, Left };
inline constexpr int kNumBowelRegions = 3;
/// What the trainee does with the case; decides the instruments the scene needs.
enum class TrainingTask : std::uint8_t { Intubation, Detection, Polypectomy };

struct Provenance {
    int formatVersion = 1;
    std::uint64_t seed = 0;
    std::uint64_t attempt = 0;  ///< rejection-sampling attempt that met the constraints
    std::string generatorVersion;
    std::string statisticsVersion;
    std::string constraints;  ///< canonical text of the constraints, empty when none
    bool operator==(const Provenance&) const = default;
};

struct Patient {
    std::string givenName;
    std::string familyName;
    Sex sex = Sex::Female;
    int age = 0;        ///< years
    double height = 0;  ///< m
    double weight = 0;  ///< kg
    double bmi = 0;     ///< kg/m^2
    bool operator==(const Patient&) const = default;
};

struct History {
    bool priorAbdominalSurgery = false;
    bool hysterectomy = false;
    Anticoagulant anticoagulant = Anticoagulant::None;
    bool operator==(const History&) const = default;
};

struct CaseAnatomy {
    std::array<double, geometry::kNumSegments> length{};    ///< m, by Segment
    std::array<double, geometry::kNumSegments> diameter{};  ///< distended, m
    double ascendingMobileFraction = 0;                     ///< 1
    bool descendingMobile = false;
    double transverseMesenteryHeight = 0;   ///< m
    double sigmoidMesenteryHeight = 0;      ///< m
    double mobileColonMesenteryHeight = 0;  ///< m
    bool operator==(const CaseAnatomy&) const = default;

    /// The colon's length along its centreline, anus to cecum: the segments' lengths summed, m.
    [[nodiscard]] double colonLength() const
    {
        double total = 0.0;
        for (const double l : length) {
            total += l;
        }
        return total;
    }
};

struct CaseTissue {
    double wallYoungModulus = 0;        ///< Pa
    double wallThickness = 0;           ///< m
    double mesenteryModulus = 0;        ///< Pa
    double mesenteryThickness = 0;      ///< m
    double adhesionStiffness = 0;       ///< N/m
    double surroundingDampingRate = 0;  ///< 1/s
    bool operator==(const CaseTissue&) const = default;
};

/// A place on the wall: segment, distance from the segment's anal end (m) and
/// clock-face angle around the centreline (rad, 0 at 12 o'clock, clockwise
/// seen from the anus).
struct WallPlace {
    Segment segment = Segment::Rectum;
    double position = 0;
    double clockAngle = 0;
    bool operator==(const WallPlace&) const = default;
};

struct Lesion {
    WallPlace place;
    double size = 0;  ///< largest diameter, m
    Paris paris = Paris::Is;
    Histology histology = Histology::TubularLowGrade;
    double stiffness = 0;  ///< Young's modulus, Pa
    Colour colour = Colour::Isochromatic;
    Surface surface = Surface::Smooth;
    int niceType = 1;     ///< NICE narrow-band imaging class 1-3
    double missRate = 0;  ///< chance an average endoscopist misses it, 1
    bool operator==(const Lesion&) const = default;
};

struct Diverticulum {
    WallPlace place;
    double diameter = 0;  ///< m
    bool operator==(const Diverticulum&) const = default;
};

struct Adhesion {
    WallPlace place;
    bool operator==(const Adhesion&) const = default;
};

struct Preparation {
    int boston = 3;            ///< BBPS segment score 0-3
    double residualStool = 0;  ///< fraction of the mucosa covered, 1
    double residualFluid = 0;  ///< m^3
    bool operator==(const Preparation&) const = default;
};

struct Environment {
    std::array<Preparation, kNumBowelRegions> preparation{};  ///< by BowelRegion
    double insufflationPressure = 0;                          ///< Pa
    double insufflationCompliance = 1;                        ///< 1
    bool operator==(const Environment&) const = default;

    [[nodiscard]] int bostonTotal() const
    {
        return preparation[0].boston + preparation[1].boston + preparation[2].boston;
    }
};

struct DifficultyFactor {
    std::string name;
    double points = 0;
    bool operator==(const DifficultyFactor&) const = default;
};

struct Difficulty {
    int level = 1;  ///< 1-5
    std::vector<DifficultyFactor> factors;
    bool operator==(const Difficulty&) const = default;
};

struct Case {
    Provenance provenance;
    Patient patient;
    Indication indication = Indication::Screening;
    History history;
    CaseAnatomy anatomy;
    CaseTissue tissue;
    std::vector<Lesion> lesions;
    std::vector<Diverticulum> diverticula;
    ColitisExtent colitis = ColitisExtent::None;
    int hemorrhoidGrade = 0;  ///< 0 none, 1-4
    std::vector<Adhesion> adhesions;
    Environment environment;
    Difficulty difficulty;
    TrainingTask task = TrainingTask::Intubation;
    bool operator==(const Case&) const = default;
};

/// Adenomas: tubular, tubulovillous and villous histologies.
[[nodiscard]] bool isAdenoma(Histology histology);
[[nodiscard]] bool isSerrated(Histology histology);
/// Advanced adenoma: an adenoma >= 10 mm, or with a villous component or
/// high-grade dysplasia.
[[nodiscard]] bool isAdvancedAdenoma(const Lesion& lesion);
[[nodiscard]] bool isFlatOrDepressed(Paris paris);
/// Proximal colon: cecum to the splenic flexure.
[[nodiscard]] bool isProximal(Segment segment);
/// Which BBPS region scores a segment: right (cecum, ascending), transverse
/// (with both flexures), left (descending, sigmoid, rectum).
[[nodiscard]] BowelRegion bowelRegion(Segment segment);

}  // namespace colonosim::cases
