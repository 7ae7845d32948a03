#pragma once
/// \file
/// Declared parameters of the colonoscope (SI; see ../params/Parameter.h).
/// Sources: reference/physical-parameters.md (colonoscope table), seed 001
/// (de Visser et al. 2010, section 2.5) and Rozeboom et al., Endosc Int Open
/// 2016 for the tip angulation. Values marked "assumption" have no measured
/// source.

#include "simcore/params/Parameter.h"

#include <numbers>
#include <span>

namespace colonosim::scope {

using params::Field;
using params::ParameterSpec;

inline constexpr double kDegree = std::numbers::pi / 180.0;

struct ScopeParameters {
    static constexpr ParameterSpec workingLengthSpec{
        "workingLength",
        "m",
        1.7,
        1.0,
        2.0,
        "insertion tube working length",
        "manufacturer class figures (1.3-1.7 m adult; Olympus CF-Q160AL is a 1.7 m class scope), unverified"};
    static constexpr ParameterSpec outerDiameterSpec{
        "outerDiameter",
        "m",
        0.013,
        0.010,
        0.016,
        "insertion tube outer diameter",
        "manufacturer class figures (12-14 mm adult), unverified"};
    static constexpr ParameterSpec flexuralRigiditySpec{
        "flexuralRigidity",
        "N m^2",
        0.033,
        0.005,
        0.2,
        "EI of the insertion tube (measured 0.026-0.040; the wider range admits test rods)",
        "flexural/torsional rigidity study (Olympus CF-140S): 0.026-0.040 N m^2, ~17% lower at 37 C"};
    static constexpr ParameterSpec torsionalRigiditySpec{
        "torsionalRigidity",
        "N m^2",
        0.44,
        0.05,
        2.0,
        "GJ of the insertion tube (torque per twist per length)",
        "same study: Olympus 68-88 N cm^2 per degree, mean 76 = 0.44 N m^2/rad"};
    static constexpr ParameterSpec linearDensitySpec{"linearMassDensity",
                                                     "kg/m",
                                                     0.2,
                                                     0.05,
                                                     1.0,
                                                     "mass per length of the insertion tube (for gravity)",
                                                     "assumption: about 0.2 kg/m for a 13 mm tube"};
    static constexpr ParameterSpec numNodesSpec{"numNodes",
                                                "1",
                                                80.0,
                                                10.0,
                                                400.0,
                                                "nodes of the discrete rod over the working length",
                                                "seed 001 (80-100 nodes for the scope)"};
    static constexpr ParameterSpec bendingSectionSpec{"bendingSectionLength",
                                                      "m",
                                                      0.10,
                                                      0.03,
                                                      0.2,
                                                      "length of the dial-steered tip bending section",
                                                      "Rozeboom et al., Endosc Int Open 2016 (about 10 cm)"};
    static constexpr ParameterSpec maxUpDownSpec{
        "maxUpDownAngulation",
        "rad",
        180.0 * kDegree,
        0.0,
        210.0 * kDegree,
        "clinical limit of the up/down dial angulation (nominal 180 deg; most scopes reach less)",
        "Rozeboom et al., Endosc Int Open 2016 (only 2 of 20 scopes reached the nominal maximum)"};
    static constexpr ParameterSpec maxLeftRightSpec{
        "maxLeftRightAngulation",
        "rad",
        160.0 * kDegree,
        0.0,
        210.0 * kDegree,
        "clinical limit of the left/right dial angulation (nominal 160 deg)",
        "Rozeboom et al., Endosc Int Open 2016"};
    static constexpr ParameterSpec iterationsSpec{
        "solverIterations", "1", 50.0, 1.0, 1000.0, "chain-solver iterations per step", "seed 001 (50)"};
    static constexpr ParameterSpec relaxationSpec{
        "solverRelaxation",
        "1",
        0.5,
        0.05,
        1.0,
        "under-relaxation of the chain solver's deformation increment (eq 4: dTheta = w F / k)",
        "assumption: 1 (the paper's eq 4) fails to settle at PL^2/EI = 4; 0.5 converges there in 14 "
        "iterations, but not at PL^2/EI = 8 (tests/scope)"};
    static constexpr ParameterSpec jointDampingSpec{
        "jointDampingRatio",
        "1",
        1.0,
        0.0,
        5.0,
        "damping ratio zeta of each joint against the inertia I of the scope beyond it, "
        "D = 2 zeta sqrt(K I) / dt, in the chain and in the contact compliance alike (0: quasi-static)",
        "model choice: the quasi-static rod has no inertia, so a load change moved the free tip tens of "
        "millimetres in one step; critical damping (1) removes those jumps and leaves the statics unchanged"};

    static constexpr ParameterSpec maxNodeStepSpec{
        "maxNodeStep",
        "m",
        0.2,
        1.0e-3,
        1.0,
        "step guard: a chain solve that moves a node further than this from where the step began is refused "
        "and solved again with the joints' damping raised fourfold (at most three times)",
        "model choice: 0.2 m in one 1 ms step is 200 m/s, far beyond what the hands (0.5 m/s at most) or "
        "the shaft's whip produce, so it refuses only a diverging solve: on the expert's runs on generated "
        "seed 3 and on the redundant-sigmoid patient of seed 1 (construct_validity --require "
        "redundant_sigmoid) it turned handle force peaks of 40.2 and 552.4 N into 10.0 and 9.2 N with 3 "
        "and 4 refused steps, and the hooked hard case, whose tip jumps 10-40 mm a step, runs exactly as "
        "unguarded; 10 mm holds more but raises two hard cases' peak handle force above the haptic "
        "device's 25 N (35.5 and 31.1 N; README, known limits)"};

    double workingLength = workingLengthSpec.defaultValue;
    double outerDiameter = outerDiameterSpec.defaultValue;
    double flexuralRigidity = flexuralRigiditySpec.defaultValue;
    double torsionalRigidity = torsionalRigiditySpec.defaultValue;
    double linearMassDensity = linearDensitySpec.defaultValue;
    double numNodes = numNodesSpec.defaultValue;
    double bendingSectionLength = bendingSectionSpec.defaultValue;
    double maxUpDownAngulation = maxUpDownSpec.defaultValue;
    double maxLeftRightAngulation = maxLeftRightSpec.defaultValue;
    double solverIterations = iterationsSpec.defaultValue;
    double solverRelaxation = relaxationSpec.defaultValue;
    double jointDampingRatio = jointDampingSpec.defaultValue;
    double maxNodeStep = maxNodeStepSpec.defaultValue;

    [[nodiscard]] static std::span<const Field<ScopeParameters>> fields();
    /// Throws ParameterError naming field, value and range; counts must be whole.
    void validate() const;
};

}  // namespace colonosim::scope
