#pragma once
/// \file
/// Declared parameters of the colon wall, its fixations and its environment
/// (SI; see ../params/Parameter.h). Sources: reference/physical-parameters.md
/// and reference/population-statistics.md; a value marked "assumption" has no
/// measured source and is documented in docs/calibration.md.

#include "simcore/params/Parameter.h"
#include "simcore/physics/Gravity.h"

#include <span>

namespace colonosim::physics {

using params::Field;
using params::ParameterSpec;

struct TissueParameters {
    static constexpr ParameterSpec youngModulusSpec{
        "wallYoungModulus",
        "Pa",
        1.74e6,
        0.5e6,
        2.0e7,
        "Young's modulus of the colon wall, human, longitudinal, at 10 cm/s",
        "J Biomech 91:102, 2019 (1.74 MPa at 10 cm/s; 5.18 MPa recto-sigmoid, SpringerPlus 2015)"};
    static constexpr ParameterSpec thicknessSpec{"wallThickness",
                                                 "m",
                                                 2.0e-3,
                                                 0.5e-3,
                                                 4.0e-3,
                                                 "distended wall thickness",
                                                 "radiology references: < 3 mm distended"};
    static constexpr ParameterSpec densitySpec{"wallDensity",
                                               "kg/m^3",
                                               1040.0,
                                               900.0,
                                               1200.0,
                                               "wall tissue density (gives node masses)",
                                               "assumption: typical soft-tissue density"};
    static constexpr ParameterSpec shearRatioSpec{
        "shearStiffnessRatio",
        "1",
        0.5,
        0.0,
        2.0,
        "stiffness of the crossing (shear) springs relative to the structural formula",
        "assumption; structural springs are calibrated with it in place (docs/calibration.md)"};
    static constexpr ParameterSpec bendingRatioSpec{
        "bendingStiffnessRatio",
        "1",
        0.02,
        0.0,
        0.5,
        "stiffness of the springs across adjacent triangles (torsion between triangles) "
        "relative to the structural formula",
        "assumption (NASA paper's torsion springs); no measured wall bending rigidity in the reference"};
    static constexpr ParameterSpec haustralAxialSpec{
        "haustralAxialRatio",
        "1",
        1.0,
        0.01,
        1.0,
        "axial membrane stiffness of the colon wall as a tube relative to its hoop stiffness E t: the wall "
        "springs are calibrated so that an axial load stretches the tube as a wall of axial stiffness "
        "ratio x E t would, and the tube bends as a beam of rigidity ratio x E t pi r^3; the hoop "
        "(insufflation) compliance stays that of E t",
        "model choice: 1 keeps the runs the README measured bit for bit. With 1 the model tube of radius "
        "2 cm bends as a beam of 0.086 N m^2, over twice the colonoscope's 0.026-0.040 "
        "(reference/physical-parameters.md), and guides the scope like a pipe; the haustral folds make the "
        "real wall a bellows that unfolds before it stretches, about (t/h)^2 of a flat strip for folds h "
        "deep (0.04-0.16 for 5-10 mm folds of a 2 mm wall; no measured value)"};
    static constexpr ParameterSpec dampingTimeSpec{
        "dampingTime",
        "s",
        5.0e-5,
        0.0,
        1.0e-3,
        "beta in c = beta k for every wall, mesentery and anchor spring (stiffness-proportional damping)",
        "assumption, no measured value: a damping ratio of 0.39 in the highest wall mode of the default "
        "colon (14,137 rad/s; tests/procedure/ProcedureLoopTest.cpp). Half of it, 0.2, would let symplectic "
        "Euler take 12 substeps a loop step instead of 14, but a colon pressed by a still scope then kept "
        "ringing: 1.3 mJ and a handle force swinging by 2 N 1 s after the scope stopped"};
    static constexpr ParameterSpec transverseDampingSpec{
        "transverseDampingRatio",
        "1",
        1.0,
        0.0,
        1.0,
        "fraction of each wall spring's damping beta k that acts on the whole relative velocity of its "
        "two nodes rather than on the rate of stretch alone (1: the viscosity of a tissue)",
        "model choice: damped only along the springs, the wall's out-of-plane modes were left with the "
        "surrounding drag alone, and under the expert at 10 s 446 wall nodes vibrated above 0.1 m/s at "
        "about 130-250 Hz (up to 1.7 m/s); at 1 the fastest node moves 0.05 m/s"};
    static constexpr ParameterSpec mesenteryModulusSpec{
        "mesenteryModulus",
        "Pa",
        0.5e6,
        0.088e6,
        6.858e6,
        "small-strain modulus of the mesentery",
        "White et al. (porcine mesocolon, mesentery and peritoneum 0.088-6.858 MPa)"};
    static constexpr ParameterSpec mesenteryThicknessSpec{
        "mesenteryThickness", "m", 1.0e-3, 0.2e-3, 5.0e-3, "thickness of the mesenteric sheet", "assumption"};
    static constexpr ParameterSpec stiffeningStrainSpec{
        "mesenteryStiffeningStrain",
        "1",
        0.3,
        0.05,
        1.0,
        "strain at which the mesentery's tangent stiffness has quadrupled",
        "assumption: soft-tissue toe region; White et al. report failure stretch 1.77-3.18"};
    static constexpr ParameterSpec maxStrainSpec{
        "mesenteryMaxStrain",
        "1",
        0.77,
        0.1,
        2.18,
        "strain beyond which the mesentery stiffens no further (failure onset)",
        "White et al.: failure stretch 1.77-3.18 (strain 0.77-2.18)"};
    static constexpr ParameterSpec retroperitonealSpec{
        "retroperitonealStiffness",
        "N/m",
        200.0,
        10.0,
        5000.0,
        "stiffness binding each node of a fixed segment to its rest position",
        "assumption: a fixed segment moves a few mm under the 10 N handle forces of the reference"};
    static constexpr ParameterSpec adhesionSpec{
        "adhesionStiffness",
        "N/m",
        500.0,
        10.0,
        10000.0,
        "stiffness of an adhesion anchor",
        "assumption: stiffer than the retroperitoneal binding (prior surgery)"};

    static constexpr ParameterSpec surroundingDampingSpec{
        "surroundingDampingRate",
        "1/s",
        20.0,
        0.0,
        200.0,
        "alpha in f = -alpha m v: drag of the surrounding viscera on the wall",
        "assumption: damps the ~1-3 Hz pendulum modes of the colon on its mesentery within about 0.2 s"};

    static constexpr ParameterSpec selfContactSpec{
        "selfContactStiffness",
        "N/m",
        2000.0,
        0.0,
        20000.0,
        "k in f = k delta between two parts of the colon whose lumens overlap by delta (LumenSelfContact.h); "
        "0 lets them pass into each other",
        "assumption: the 10 N handle force exceeded only 5% of the time (Appleyard et al., Gastrointest "
        "Endosc 2000), passed on to a fold, presses its limbs 5 mm into each other"};

    double wallYoungModulus = youngModulusSpec.defaultValue;
    double wallThickness = thicknessSpec.defaultValue;
    double wallDensity = densitySpec.defaultValue;
    double shearStiffnessRatio = shearRatioSpec.defaultValue;
    double bendingStiffnessRatio = bendingRatioSpec.defaultValue;
    double haustralAxialRatio = haustralAxialSpec.defaultValue;
    double dampingTime = dampingTimeSpec.defaultValue;
    double transverseDampingRatio = transverseDampingSpec.defaultValue;
    double mesenteryModulus = mesenteryModulusSpec.defaultValue;
    double mesenteryThickness = mesenteryThicknessSpec.defaultValue;
    double mesenteryStiffeningStrain = stiffeningStrainSpec.defaultValue;
    double mesenteryMaxStrain = maxStrainSpec.defaultValue;
    double retroperitonealStiffness = retroperitonealSpec.defaultValue;
    double adhesionStiffness = adhesionSpec.defaultValue;
    double surroundingDampingRate = surroundingDampingSpec.defaultValue;
    double selfContactStiffness = selfContactSpec.defaultValue;

    [[nodiscard]] static std::span<const Field<TissueParameters>> fields();
    void validate() const;
};

struct EnvironmentParameters {
    static constexpr ParameterSpec gravitySpec{
        "gravity", "m/s^2", 9.81, 0.0, 20.0, "gravitational acceleration", "standard gravity"};
    static constexpr ParameterSpec pressureSpec{
        "insufflationPressure",
        "Pa",
        2000.0,
        0.0,
        10800.0,
        "gauge pressure of insufflated gas in the lumen (2000 Pa = 15 mmHg)",
        "9-57 mmHg with the tip free during colonoscopy; cecum ruptures at 81 mmHg (air-pressure injury "
        "study)"};

    double gravity = gravitySpec.defaultValue;
    double insufflationPressure = pressureSpec.defaultValue;
    PatientPosition patientPosition = PatientPosition::LeftLateral;

    [[nodiscard]] static std::span<const Field<EnvironmentParameters>> fields();
    void validate() const;
};

}  // namespace colonosim::physics
