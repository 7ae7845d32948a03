#pragma once
/// \file
/// The numbers of a case file: each is declared once with its XML element
/// name, the unit the file writes, how many SI units one file unit is, the
/// decimals written and the valid range in file units. The same declaration
/// rounds generated values, writes them, reads them and names them in
/// validation messages.
///
/// Rounding: a generated SI value v is stored as parse(format(v / k)) * k, with
/// k = siPerUnit and format = std::to_chars fixed with `decimals` digits, which
/// is exactly what reading the written text gives. So a written case reads
/// back bit for bit, and a 1-ulp difference in v (another compiler's
/// arithmetic) could only change the file if v / k sat within an ulp of a
/// rounding midpoint; the generator's arithmetic avoids libm (see
/// DeterministicMath.h) so that it does not differ in the first place.

#include "simcore/params/Parameter.h"

#include <optional>
#include <string>
#include <string_view>

namespace colonosim::cases {

struct Quantity {
    std::string_view element;
    std::string_view unit;
    double siPerUnit;
    int decimals;
    double min;  ///< file units
    double max;  ///< file units
    std::string_view help;

    /// v rounded to what the file can hold (SI in, SI out).
    [[nodiscard]] double quantise(double si) const;
    /// Clamped to a declared parameter's range, then rounded, staying inside
    /// the range (one written step inward where rounding would leave it; a
    /// bound that comes back an ulp outside stays: see SceneTranslation).
    [[nodiscard]] double quantiseWithin(double si, const params::ParameterSpec& spec) const;
    /// The file's text for an SI value.
    [[nodiscard]] std::string format(double si) const;
    [[nodiscard]] bool accepts(double fileValue) const;
    /// The same quantity with the range of a declared simulator parameter.
    [[nodiscard]] Quantity withRangeOf(const params::ParameterSpec& spec) const;
};

/// Fixed-point text with `decimals` digits (std::to_chars: exact, locale-free).
[[nodiscard]] std::string formatFixed(double value, int decimals);
/// Parses a whole decimal number (std::from_chars); nullopt for anything else,
/// including trailing text, "nan" and "inf".
[[nodiscard]] std::optional<double> parseNumber(std::string_view text);

namespace quantity {
inline constexpr double kMmHg = 133.322387415;

inline constexpr Quantity age{"age", "year", 1.0, 0, 18, 110, "age at the examination"};
inline constexpr Quantity height{"height", "cm", 0.01, 1, 120, 230, "body height"};
inline constexpr Quantity weight{"weight", "kg", 1.0, 1, 20, 400, "body weight"};
inline constexpr Quantity bmi{"bmi", "kg/m^2", 1.0, 1, 10, 100, "body mass index, weight / height^2"};

inline constexpr Quantity segmentLength{"length", "cm", 0.01, 1, 0, 0, "segment length along the centreline"};
inline constexpr Quantity segmentDiameter{"diameter", "mm", 0.001, 1, 0, 0, "distended lumen diameter"};
inline constexpr Quantity ascendingMobileFraction{
    "ascending_mobile_fraction", "1", 1.0, 2, 0, 1, "mobile fraction of ascending colon and cecum"};
inline constexpr Quantity transverseMesenteryHeight{"transverse_mesentery_height", "cm", 0.01, 1, 0, 0,
                                                    "transverse mesocolon height"};
inline constexpr Quantity sigmoidMesenteryHeight{"sigmoid_mesentery_height", "cm", 0.01, 1, 0, 0,
                                                 "sigmoid mesocolon height"};
inline constexpr Quantity mobileColonMesenteryHeight{
    "mobile_colon_mesentery_height",
    "cm",
    0.01,
    1,
    0,
    0,
    "mesentery height of a mobile ascending or descending colon"};

inline constexpr Quantity wallYoungModulus{"wall_young_modulus",        "MPa", 1e6, 3, 0, 0,
                                           "colon wall Young's modulus"};
inline constexpr Quantity wallThickness{"wall_thickness", "mm", 0.001, 2, 0, 0, "distended wall thickness"};
inline constexpr Quantity mesenteryModulus{"mesentery_modulus", "MPa", 1e6, 3, 0, 0, "mesentery modulus"};
inline constexpr Quantity mesenteryThickness{"mesentery_thickness",       "mm", 0.001, 2, 0, 0,
                                             "mesenteric sheet thickness"};
inline constexpr Quantity adhesionStiffness{"adhesion_stiffness",       "N/m", 1.0, 0, 0, 0,
                                            "adhesion anchor stiffness"};
inline constexpr Quantity surroundingDampingRate{"surrounding_damping_rate",       "1/s", 1.0, 1, 0, 0,
                                                 "drag of the surrounding viscera"};

inline constexpr Quantity position{
    "position", "cm", 0.01, 1, 0, 70, "distance from the segment's anal end, at most the segment's length"};
inline constexpr Quantity clockAngle{
    "clock_angle", "deg", 0.017453292519943295, 0, 0, 359, "clock-face angle, 0 at 12 o'clock"};
inline constexpr Quantity lesionSize{"size", "mm", 0.001, 0, 1, 100, "largest lesion diameter"};
inline constexpr Quantity lesionStiffness{"stiffness", "MPa", 1e6, 2, 0.1, 100, "lesion Young's modulus"};
inline constexpr Quantity niceType{"nice_type", "1", 1.0, 0, 1, 3, "NICE narrow-band imaging class"};
inline constexpr Quantity missRate{
    "miss_rate", "1", 1.0, 3, 0, 1, "chance that an average endoscopist misses it"};
inline constexpr Quantity diverticulumDiameter{
    "diameter", "mm", 0.001, 1, 1, 30, "diverticulum neck diameter"};
inline constexpr Quantity hemorrhoidGrade{"hemorrhoid_grade", "1", 1.0, 0, 0, 4, "hemorrhoid grade, 0 none"};

inline constexpr Quantity boston{"boston", "1", 1.0, 0, 0, 3, "Boston Bowel Preparation Scale segment score"};
inline constexpr Quantity residualStool{
    "residual_stool", "1", 1.0, 2, 0, 1, "fraction of mucosa covered by stool"};
inline constexpr Quantity residualFluid{"residual_fluid", "mL", 1e-6, 0, 0, 2000, "residual fluid volume"};
inline constexpr Quantity insufflationPressure{"insufflation_pressure",        "mmHg", kMmHg, 1, 0, 0,
                                               "working insufflation pressure"};
inline constexpr Quantity insufflationCompliance{
    "insufflation_compliance", "1", 1.0, 2, 0.1, 10, "compliance factor; pressure = reference / compliance"};

inline constexpr Quantity difficultyLevel{"level", "1", 1.0, 0, 1, 5, "difficulty 1 (easy) to 5"};
inline constexpr Quantity difficultyPoints{"points", "1", 1.0, 1, 0, 10, "points a difficulty factor adds"};
}  // namespace quantity

}  // namespace colonosim::cases
