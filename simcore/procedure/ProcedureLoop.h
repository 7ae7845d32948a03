#pragma once
/// \file
/// The fixed-step procedure loop (1 kHz by default; dt never comes from the
/// wall clock). One step turns one InputSample into motion, forces and a
/// recorded frame:
///   1. the input is validated at the device boundary (a refused sample is
///      recorded as an event and the last valid one is used);
///   2. the handle (insertion, shaft rotation) and the dials drive the scope;
///   3. scope-wall contact is measured on the current shapes against the
///      lumen (LumenContact: every scope node's signed depth in its own
///      section of the tube, so it cannot tunnel); ContactCoupling settles
///      the normal forces in one Newton step with the compliance of the rod
///      and of the wall's nodes over the step, and the scope's loads go to
///      the chain solver while their opposites are held on the wall's nodes
///      over the tissue substeps;
///   The colon is first settled to static equilibrium under gravity and
///   insufflation, so nodes at rest may sleep.
///   4. the scope's chain solver runs its iterations; the colon advances one
///      loop step with the substeps its stability bound asks for;
///   5. outputs: the handle force and torque (the base load of the chain),
///      the tip pose, the loop state, discomfort and perforation, handed to
///      the recorder; the raw input is appended to the trace. The contact
///      loads of the step feed the bleeding marks (BleedingMarks.h); a new
///      mark is a contact_bleeding event at the step's time.
/// Air and suction change the insufflation pressure at declared rates.
/// Everything is deterministic: the same case, build and input trace give a
/// bit-identical recording.

#include "simcore/contact/LumenContact.h"
#include "simcore/geometry/ColonAnatomy.h"
#include "simcore/physics/ActiveRegion.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/StaticSolver.h"
#include "simcore/physics/TissueSimulation.h"
#include "simcore/procedure/BleedingMarks.h"
#include "simcore/procedure/ContactCoupling.h"
#include "simcore/procedure/Discomfort.h"
#include "simcore/procedure/InputTrace.h"
#include "simcore/procedure/Insufflator.h"
#include "simcore/procedure/LesionView.h"
#include "simcore/procedure/LoopDetector.h"
#include "simcore/procedure/Recorder.h"
#include "simcore/procedure/WallSite.h"
#include "simcore/render/WallSurface.h"
#include "simcore/scope/Colonoscope.h"

#include <memory>

namespace colonosim::procedure {

struct ProcedureSettings {
    physics::TissueParameters tissue;
    physics::EnvironmentParameters environment;
    /// The wall springs' factors for tissue.haustralAxialRatio 1
    /// (docs/calibration.md); another ratio scales them as
    /// physics::wallCalibrationFor() finds.
    physics::StiffnessCalibration calibration{0.5, 0.97};
    physics::SteppingPolicy stepping;
    bool activeRegion = true;
    scope::ScopeParameters scope;
    contact::ContactParameters contact;
    RecorderParameters recorder;
    LoopParameters loops;
    DiscomfortParameters discomfort;
    BleedingParameters bleeding;
    /// The case's lesions (LesionView.h), and the view they are seen by.
    std::vector<LesionSite> lesions;
    /// The case's adhesions (prior surgery): each binds the wall node nearest
    /// its place to where that node lies at rest, with the anchor stiffness
    /// tissue.adhesionStiffness. At most kMaxAdhesions.
    std::vector<WallSite> adhesions;
    static constexpr int kMaxAdhesions = 32;
    render::RenderParameters viewing;
    InsufflatorParameters insufflator;
};

/// What a haptic device and the camera need after each step.
struct ProcedureOutputs {
    double handleForce = 0.0;   ///< N along the insertion direction (+ resists insertion)
    double handleTorque = 0.0;  ///< N m about the shaft
    scope::TipPose tip;
};

/// Takes a step's handle load the moment the scope's chain solve has it,
/// before the colon's substeps and the recording (steps 4-5 below): a
/// haptic device is answered within the scope's part of the step, not the
/// whole step. The values are those outputs() holds after the step.
class HandleLoadSink {
public:
    virtual ~HandleLoadSink() = default;
    /// N along the insertion direction (+ resists insertion), N m about the shaft.
    virtual void handleLoadReady(double handleForce, double handleTorque) = 0;
};

class ProcedureLoop {
public:
    /// Builds the colon body from `anatomy` (which must outlive the loop) and
    /// the scope at the anus. Throws ParameterError for invalid settings.
    ProcedureLoop(const geometry::ColonAnatomy& anatomy, const ProcedureSettings& settings);

    /// One loop step; never throws. `early`, when given, gets the step's
    /// handle load as soon as the scope has it (HandleLoadSink); it only
    /// reads, so the step is the same with or without it.
    const ProcedureOutputs& step(const InputSample& input, HandleLoadSink* early = nullptr);

    /// Records that input device `name` connected (or disconnected) now.
    void noteDevice(const std::string& name, bool connected)
    {
        m_recorder.note(m_time, connected ? EventKind::DeviceConnected : EventKind::DeviceDisconnected, name);
    }

    [[nodiscard]] double time() const { return m_time; }
    [[nodiscard]] const ProcedureOutputs& outputs() const { return m_outputs; }
    [[nodiscard]] const ProcedureFrame& lastFrame() const { return m_frame; }
    [[nodiscard]] const Recording& recording() const { return m_recorder.recording(); }
    /// m: the colon's centreline length, as the recorder uses it (the
    /// anatomy's, whatever settings.recorder.colonLength says); what scoring's
    /// geometric mucosa estimate needs (ScoringContext::colonLength).
    [[nodiscard]] double colonLength() const { return m_recorder.parameters().colonLength; }
    /// The case's lesions on the wall, as the loop's "lesion in view" sees them.
    [[nodiscard]] const LesionView& lesions() const { return m_lesions; }
    /// Whether the recording holds the cecum_reached event (the tip within
    /// RecorderParameters::cecumDepth of the end of the colon).
    [[nodiscard]] bool cecumReached() const { return m_recorder.cecumReached(); }
    [[nodiscard]] const InputTrace& trace() const { return m_trace; }
    [[nodiscard]] const scope::Colonoscope& scope() const { return m_scope; }
    [[nodiscard]] const physics::ColonBody& colon() const { return m_colon; }
    [[nodiscard]] const LoopDetector& loops() const { return m_loops; }
    [[nodiscard]] const physics::TissueSimulation& tissue() const { return *m_simulation; }
    /// The static solve of the colon's rest state the procedure starts from.
    [[nodiscard]] const physics::StaticResult& restSolve() const { return m_restSolve; }
    /// The deformed lumen and each scope node's contact, as of the last step.
    [[nodiscard]] const contact::LumenContact& lumen() const { return m_contact; }
    [[nodiscard]] const ContactCoupling& coupling() const { return m_coupling; }
    /// Contact solves of the last step (1 to contact.couplingPasses).
    [[nodiscard]] int couplingPasses() const { return m_passes; }
    /// N: a further coupling pass is skipped once no load component changed
    /// by more than this in the last one (only while every pass sweeps to
    /// contact.sweepTolerance: with a looser contact.passSweepTolerance every
    /// step runs all its passes, so that the last is solved to the full
    /// tolerance).
    static constexpr double kPassTolerance = 1e-3;
    /// The contact bleeding marks so far, placed on the wall's chart for the
    /// endoscope view; bleeding() has the model's marks (rest points, forces).
    [[nodiscard]] const std::vector<render::BleedingMark>& bleedingMarks() const { return m_viewMarks; }
    [[nodiscard]] const BleedingMarks& bleeding() const { return m_bleeding; }

private:
    void applyContact();
    /// One contact solve: the contacts of the scope shape `scope` (3 x n)
    /// against m_wallAhead, the coupling's loads for them, and the chain
    /// solved under those loads. `wallMoved` false: the lumen's rings are the
    /// last solve's.
    /// `lastSolve`: no further solve follows this one in the step.
    void solveContact(const Eigen::Matrix3Xd& scope, int addedAtBase, bool wallMoved, bool lastSolve);
    /// contact.spinFriction: each node's spin over the last step, and the
    /// contact points' (`shift` nodes entered at the base since).
    void measureSpin(int shift);
    void observe();
    void updateBleeding();

    const geometry::ColonAnatomy& m_anatomy;
    ProcedureSettings m_settings;
    physics::ColonBody m_colon;
    physics::StaticResult m_restSolve;
    std::unique_ptr<physics::TissueSimulation> m_simulation;
    std::unique_ptr<physics::ActiveRegion> m_region;
    scope::Colonoscope m_scope;
    contact::LumenContact m_contact;
    Eigen::VectorXd m_wallCompliance;  ///< dt^2 / (2 m) per wall node (0 fixed), m/N
    ContactCoupling m_coupling;
    std::vector<double> m_nodeArcs;  ///< each scope node's place along the colon (lumen station), m
    LoopDetector m_loops;
    /// Loop steps between two analyses of the shaft (LoopParameters::analysisInterval).
    int m_loopAnalysisSteps = 1;
    DiscomfortModel m_discomfort;
    LesionView m_lesions;
    BleedingMarks m_bleeding;
    std::vector<WallLoad> m_wallLoads;              ///< this step's contact loads on the wall
    std::vector<render::BleedingMark> m_viewMarks;  ///< m_bleeding's marks for the view
    long m_bleedingRevision = 0;
    Recorder m_recorder;
    InputTrace m_trace;
    InputSample m_input;
    ProcedureFrame m_frame;
    ProcedureOutputs m_outputs;
    Eigen::Matrix3Xd m_scopeNow, m_scopePrevious, m_scopeVelocity;
    Eigen::Matrix3Xd m_wallAhead;     ///< wall positions carried one step by their velocities
    Eigen::Matrix3Xd m_scopeAligned;  ///< the previous shape aligned from the tip (continuous detection)
    Eigen::Matrix3Xd m_scopePass;     ///< the shape a coupling pass re-measures the contact on
    Eigen::Matrix3Xd m_passLoads;     ///< the previous pass's contact loads
    /// The contact points (ContactPoints.h) of the shape being measured and their velocities.
    Eigen::Matrix3Xd m_points, m_pointVelocity;
    // contact.spinFriction: each node's element frame at the last step's
    // start, and the spin about the shaft's axis of each node and contact
    // point over the last step (rad/s, world).
    std::vector<Eigen::Matrix3d> m_framePrevious;
    Eigen::Matrix3Xd m_nodeSpin, m_pointSpin;
    int m_passes = 0;             ///< coupling passes of the last step
    double m_maxWallForce = 0.0;  ///< largest contact load on one scope node this step, N
    double m_time = 0.0;
    long m_steps = 0;
};

}  // namespace colonosim::procedure
