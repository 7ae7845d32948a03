#pragma once
/// \file
/// Patient discomfort from the three things that hurt during colonoscopy:
/// luminal pressure, mesentery stretch (looping) and wall stress.
///
/// Each is scaled to 0-10 between its pain onset and its damage level:
///   pressure: onset 20 mmHg, 10 at 70 mmHg (phasic sigmoid distension is
///     painful from 20-70 mmHg; Pain 43:377, 1990);
///   mesentery strain: onset painOnsetStrain, 10 at the declared failure
///     onset strain (White et al.: failure stretch 1.77-3.18);
///   wall stress: E times the largest tensile wall strain, onset at
///     painOnsetStress, 10 at the tensile strength 0.87 MPa (SpringerPlus 2015).
/// The instantaneous score is the largest of the three; the reported score
/// follows it through a first-order lag of time constant tau (pain is felt
/// within about a second; assumption), so the score is a smooth signal.
/// Clinical 5-point comfort scale (Gloucester scale used by the JAG):
///   1 comfortable < 1 <= 2 minimal < 3 <= 3 mild < 5 <= 4 moderate < 7.5 <= 5 severe
/// (the thresholds on the 0-10 score are an assumption).
/// Perforation: wall stress at the tensile strength, or luminal pressure
/// above the segment's rupture pressure (cecum 81 mmHg, sigmoid 169 mmHg;
/// air-pressure colon injury study).

#include "simcore/params/Parameter.h"

namespace colonosim::procedure {

struct DiscomfortParameters {
    static constexpr params::ParameterSpec pressureOnsetSpec{
        "painOnsetPressure",
        "Pa",
        2666.4,
        0.0,
        20000.0,
        "luminal pressure at which pain begins (20 mmHg)",
        "Pain 43:377, 1990: pain from 20-70 mmHg phasic sigmoid distension"};
    static constexpr params::ParameterSpec pressureMaxSpec{
        "severePainPressure",
        "Pa",
        9332.6,
        100.0,
        30000.0,
        "luminal pressure giving the highest score (70 mmHg)",
        "Pain 43:377, 1990"};
    static constexpr params::ParameterSpec strainOnsetSpec{
        "painOnsetStrain",
        "1",
        0.1,
        0.0,
        1.0,
        "mesentery strain at which pain begins",
        "assumption: looping stretches the mesentery; pain well before failure"};
    static constexpr params::ParameterSpec stressOnsetSpec{
        "painOnsetStress",
        "Pa",
        0.2e6,
        0.0,
        0.87e6,
        "wall stress at which pain begins",
        "assumption: a quarter of the tensile strength 0.87 MPa (SpringerPlus 2015)"};
    static constexpr params::ParameterSpec strengthSpec{
        "wallTensileStrength",
        "Pa",
        0.87e6,
        0.1e6,
        5e6,
        "wall stress at which the wall tears (perforation)",
        "SpringerPlus 2015: human recto-sigmoid tensile strength 0.87 MPa"};
    static constexpr params::ParameterSpec ruptureSpec{
        "rupturePressure",
        "Pa",
        10799.0,
        1000.0,
        40000.0,
        "luminal pressure at which the weakest segment (cecum, 81 mmHg) ruptures",
        "air-pressure colon injury study: cecum 81 mmHg, sigmoid 169 mmHg"};
    static constexpr params::ParameterSpec lagSpec{
        "painLag", "s", 1.0, 0.0, 10.0, "time constant with which felt pain follows its cause", "assumption"};

    double painOnsetPressure = pressureOnsetSpec.defaultValue;
    double severePainPressure = pressureMaxSpec.defaultValue;
    double painOnsetStrain = strainOnsetSpec.defaultValue;
    double mesenteryFailureStrain = 0.77;  ///< from TissueParameters::mesenteryMaxStrain
    double painOnsetStress = stressOnsetSpec.defaultValue;
    double wallTensileStrength = strengthSpec.defaultValue;
    double rupturePressure = ruptureSpec.defaultValue;
    double painLag = lagSpec.defaultValue;

    void validate() const;
};

struct DiscomfortInput {
    double luminalPressure = 0.0;  ///< Pa (gauge)
    double mesenteryStrain = 0.0;  ///< largest, 1
    double wallStress = 0.0;       ///< largest tensile, Pa
};

class DiscomfortModel {
public:
    explicit DiscomfortModel(const DiscomfortParameters& parameters);

    /// Advances by dt (s); returns the lagged 0-10 score.
    double update(const DiscomfortInput& input, double dt);
    [[nodiscard]] double score() const { return m_score; }
    /// The instantaneous (unlagged) 0-10 score of `input`.
    [[nodiscard]] double instantaneous(const DiscomfortInput& input) const;
    /// True when `input` perforates (wall at tensile strength or pressure at rupture).
    [[nodiscard]] bool perforates(const DiscomfortInput& input) const;

private:
    DiscomfortParameters m_parameters;
    double m_score = 0.0;
};

/// Gloucester-style 5-point comfort scale from the 0-10 score.
[[nodiscard]] int comfortScale(double score);

}  // namespace colonosim::procedure
