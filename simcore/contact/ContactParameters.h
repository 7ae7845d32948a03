#pragma once
/// \file
/// Declared parameters of the scope-wall contact (SI; see ../params/Parameter.h
/// and ScopeWallContact.h for the law). Sources: reference/physical-parameters.md;
/// a value marked "assumption" has no measured source.

#include "simcore/params/Parameter.h"

#include <span>

namespace colonosim::contact {

using params::Field;
using params::ParameterSpec;

struct ContactParameters {
    static constexpr ParameterSpec stiffnessSpec{
        "contactStiffness",
        "N/m",
        1.0e4,
        1.0e2,
        1.0e6,
        "penalty stiffness k_c of one scope segment on the wall: f_n = k_c depth",
        "assumption: 10 N, the handle force exceeded only 5% of the time (Appleyard et al., "
        "Gastrointest Endosc 2000), gives a penetration of about 1 mm"};
    static constexpr ParameterSpec dampingSpec{
        "contactDamping",
        "N*s/m",
        2.0,
        0.0,
        100.0,
        "normal damping c_n on the penetration rate (the normal force never pulls)",
        "assumption: damping ratio about 0.1 for a 5 g scope node on k_c = 1e4 N/m"};
    static constexpr ParameterSpec frictionSpec{
        "frictionCoefficient",
        "1",
        0.1,
        0.0,
        1.0,
        "Coulomb coefficient mu of dynamic friction, scope shaft on colon mucosa",
        "reference/physical-parameters.md: about 0.09 with good lubricant, human autopsy colon "
        "(Communications Engineering 2024); porcine bowel 0.0004-0.054 (Lyle et al. 2013)"};
    static constexpr ParameterSpec stickVelocitySpec{
        "stickVelocity",
        "m/s",
        1.0e-2,
        1.0e-4,
        1.0e-1,
        "sliding speed below which friction is viscous, mu f_n v_t / v_s (regularised stick)",
        "assumption: creep under a sub-threshold load stays below v_s; an explicit integrator "
        "needs mu f_n dt / (v_s m) < 2 on a scope node of mass m"};

    static constexpr ParameterSpec passesSpec{
        "couplingPasses",
        "1",
        3.0,
        1.0,
        8.0,
        "most times one loop step solves the contact (rounded): after the first the contact is re-measured "
        "on the shape the chain found and solved again, until no node's load changes by more than 1 mN",
        "model choice: the coupling's model is linear about the step's start shape; over the expert's "
        "first 60 s on the default colon the tip went 66 mm into the wall (5,700 steps more than a scope "
        "diameter in, through the wall by 50 s) with one solve, 8.5 mm (no step) with three, for 4% "
        "more wall time"};

    static constexpr ParameterSpec sweepsSpec{
        "couplingSweeps",
        "1",
        30.0,
        1.0,
        500.0,
        "most projected Gauss-Seidel sweeps over the nodes in contact in one contact solve (rounded); the "
        "sweeps stop earlier once no node's load changes by more than contact.sweepTolerance",
        "model choice: each sweep is one pass over the dense compliance of the m nodes in contact (m^2 3x3 "
        "blocks); build/bench/contact_stability --sweeps 30,10, the expert's first 100 s on the default "
        "colon: 10 sweeps took 0.80 of the time and left 2.2 mN at the cap, but gave 490 tip steps longer "
        "than 2 mm against 140 and 18 steps more than a scope diameter into the wall against 1"};
    static constexpr ParameterSpec sweepToleranceSpec{
        "sweepTolerance",
        "N",
        1.0e-4,
        1.0e-8,
        1.0e-1,
        "the contact solve's sweeps stop once no node's normal load changed by more than this in a sweep",
        "model choice: 0.1 mN, a hundredth of the 1 mN by which contact.couplingPasses judges the loads "
        "settled"};
    static constexpr ParameterSpec passToleranceSpec{
        "passSweepTolerance",
        "N",
        1.0e-4,
        1.0e-8,
        1.0e-1,
        "the sweeps of a contact solve that another solve of the same loop step follows (all of "
        "contact.couplingPasses but the last) stop once no node's normal load changed by more than this in a "
        "sweep; the last solve sweeps to contact.sweepTolerance. Above contact.sweepTolerance every step "
        "runs all its passes; at or below it (the default) every solve sweeps to contact.sweepTolerance and "
        "the passes stop once the loads settle",
        "model choice: off (equal to contact.sweepTolerance). At 3 mN the expert's steps from 60 s on the "
        "default colon took 42 sweeps against 81, the last solve's 26 unchanged, but two hard cases failed: "
        "the hooked shaft's handle torque reached 3.97 N m against its bound of 3.42 (4.39 at 1 mN), and the "
        "novice sprung against the cecal end pushed 31 N at the handle against the device's 25 (README, "
        "\"Full procedure step\")"};

    static constexpr ParameterSpec prefixSweepsSpec{
        "prefixSweeps",
        "1",
        1.0,
        0.0,
        1.0,
        "1: each contact-solve sweep sums the load changes' effect on a node through the rod's prefix sums, "
        "O(m) a sweep over m nodes in contact; 0: through the dense compliance, O(m^2) (the same sweeps, "
        "rounded differently; procedure/ContactCoupling.h)",
        "model choice: 1, the same solve for less work: the sweeps agree with the dense ones to 1e-15 N "
        "(tests/procedure), and the expert's first 70 s on the default colon took 1,293 against 1,424 us a "
        "step (build/bench/contact_stability --seconds 70 --seeds 0 --prefix-sweeps 1, and 0); runs measured "
        "before this default used 0 and differ from today's in their last bits and what follows from them"};

    static constexpr ParameterSpec accelerationSpec{
        "sweepAcceleration",
        "sweeps",
        0.0,
        0.0,
        10.0,
        "Anderson acceleration of the contact solve's sweeps: after each sweep the normal loads become the "
        "combination of the last this many sweeps' results whose changes cancel best, projected to "
        "lambda >= 0; 0 sweeps plainly. The sweeps still stop on a plain sweep's change "
        "(contact.sweepTolerance; procedure/ContactCoupling.h)",
        "model choice: off. From 60 s of the expert on the default colon it cut the sweeps of a solve from "
        "26.9 to 20.8 (depth 3) and 19.5 (depth 5), and the step to about 0.92 of its time, but the hard "
        "cases "
        "pass or fail by the solve's path: at 3 the hooked shaft reached 72 N and 41 N m against 25 N and "
        "3.42 N m, and the cecal end 31.6 N (README, \"Full procedure step\")"};

    static constexpr ParameterSpec elementPointsSpec{
        "elementPoints",
        "1",
        0.0,
        0.0,
        3.0,
        "contact points inside each scope element besides its two nodes (rounded): k points at "
        "t = j / (k + 1) along the element, where the wall is also measured; the load found at a point "
        "is shared by the element's two nodes in proportion to where it lies (procedure/ContactCoupling.h)",
        "model choice: 0 keeps the runs the README measured bit for bit. With the nodes alone an "
        "element's middle went 5.85 mm into the wall in a blind push round the rectosigmoid flexure, "
        "0.45 mm with 1; the novice's first 40 s on the default colon pulled up to 39.4 N on withdrawal "
        "with 0, 14.1 N with 1, at 1.35-1.96 times the step time (build/bench/contact_stability "
        "--element-points; README, known limits)"};

    static constexpr ParameterSpec stickingFrictionSpec{
        "stickingFriction",
        "1",
        0.0,
        0.0,
        1.0,
        "1: each contact point keeps its friction load from step to step and adds to it what stops the "
        "slip of the step (up to the Coulomb limit mu lambda): a point sticks to the wall until the "
        "tangential load needs more; 0: the friction is found afresh each step from the step's slip alone, "
        "regularised below the speed 2 mu lambda R / dt (procedure/ContactCoupling.h)",
        "model choice: 0 keeps the runs the README measured bit for bit. Regularised afresh, the friction "
        "is -slip dt / (2 R) wherever the slip is slower than 2 mu lambda R / dt (metres a second on a "
        "bent shaft), independent of mu: a 25 s push into a redundant sigmoid ran bit for bit the same "
        "with mu 0.1 and 0.3 (README, known limits)"};
    static constexpr ParameterSpec spinFrictionSpec{
        "spinFriction",
        "1",
        0.0,
        0.0,
        1.0,
        "1: the shaft's spin about its own axis slides its surface over the wall: a contact point's slip "
        "takes the surface's velocity (the node's less r w x n, w the spin, n the wall's normal, r the "
        "scope's radius), and the friction found for it acts at the surface, a moment (-r n) x f on the rod "
        "besides the force f at its axis; 0: the slip of the axis alone and no friction moment "
        "(procedure/ContactCoupling.h)",
        "model choice: 0 keeps the runs the README measured bit for bit. Without it a shaft turned in the "
        "colon meets no friction moment and the wall no drag from the turn: torque reaches the tip however "
        "much of the shaft lies on the wall, and a turned loop feels no sideways push from the wall "
        "(README, known limits; build/bench/construct_validity --spin-friction)"};
    static constexpr ParameterSpec sideNormalsSpec{
        "sideNormals",
        "1",
        0.0,
        0.0,
        1.0,
        "1: the wall pushes each contact point but the tip across the shaft: its load takes the wall's "
        "normal less the part along the scope's axis there (the wall's normal itself where that part "
        "leaves less than 0.2 across); 0: along the wall's normal (procedure/ContactCoupling.h)",
        "model choice: 0 keeps the runs the README measured bit for bit. A shaft lies along the wall it "
        "touches, so the wall's push on it is across it (friction apart); where the colon is pleated on the "
        "shaft the sections' cylinders tilt against it and their normals pushed along it (README, known "
        "limits; build/bench/contact_stability --side-normals)"};

    static constexpr ParameterSpec pleatSearchSpec{
        "pleatSearch",
        "1",
        0.0,
        0.0,
        1.0,
        "1: a contact point whose centre lies outside its section's wall and that no section towards its "
        "base-side neighbour's holds also takes a section on the other side (up to 16 sections from its own) "
        "whose wall holds it, where the shaft from that neighbour to the point passes through every ring "
        "between within the scope's radius of its wall (contact/LumenTube.h passesThrough); 0: only sections "
        "towards the neighbour's",
        "model choice: 0 keeps the runs the README measured bit for bit. Where the colon is pleated on the "
        "shaft, consecutive points 10 mm apart lie 5-14 sections apart in tilted, packed rings, and the walk "
        "is held with the point outside a flattened section it does not lie in (README, known limits; "
        "build/bench/contact_stability --pleat-search)"};

    static constexpr ParameterSpec relaxationSpec{
        "loadRelaxation",
        "1",
        0.3,
        0.05,
        1.0,
        "fraction omega of the solved change of the contact loads that each contact solve applies; the rest "
        "follows over the next solves (procedure/ContactCoupling.h)",
        "model choice: build/bench/contact_stability, the expert's first 50 s on four patients (the default "
        "colon and generated seeds 1-3): tip steps longer than 2 mm (faster than 2 m/s) 11,372 with omega 1, "
        "4,540 with 0.5 and 1,535 with 0.3; steps with the tip more than a scope diameter into the wall "
        "2,447, "
        "150 and 11; deepest 81, 45 and 15.6 mm"};
    static constexpr ParameterSpec stepLimitSpec{
        "stepLimit",
        "m",
        0.5e-3,
        1.0e-5,
        1.0e-2,
        "trust region of the contact solve: how far the change of a node's contact load may move it in one "
        "loop step, beyond the way its depth grew over the last step (procedure/ContactCoupling.h)",
        "model choice: 0.5 mm per 1 ms step, the 0.5 m/s insertion the contact must hold without tunnelling "
        "(issue 3); a contact that appears deep is resolved over several steps, not thrown across the lumen"};
    double contactStiffness = stiffnessSpec.defaultValue;
    double contactDamping = dampingSpec.defaultValue;
    double frictionCoefficient = frictionSpec.defaultValue;
    double stickVelocity = stickVelocitySpec.defaultValue;
    double couplingPasses = passesSpec.defaultValue;
    double couplingSweeps = sweepsSpec.defaultValue;
    double sweepTolerance = sweepToleranceSpec.defaultValue;
    double passSweepTolerance = passToleranceSpec.defaultValue;
    double prefixSweeps = prefixSweepsSpec.defaultValue;
    double sweepAcceleration = accelerationSpec.defaultValue;
    double elementPoints = elementPointsSpec.defaultValue;
    double sideNormals = sideNormalsSpec.defaultValue;
    double stickingFriction = stickingFrictionSpec.defaultValue;
    double pleatSearch = pleatSearchSpec.defaultValue;
    double spinFriction = spinFrictionSpec.defaultValue;
    double loadRelaxation = relaxationSpec.defaultValue;
    double stepLimit = stepLimitSpec.defaultValue;

    [[nodiscard]] static std::span<const Field<ContactParameters>> fields();
    void validate() const;
};

}  // namespace colonosim::contact
