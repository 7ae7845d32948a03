#include "simcore/procedure/ProcedureLoop.h"

#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/params/Parameter.h"
#include "simcore/physics/SpringCalibration.h"
#include "simcore/physics/StaticSolver.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace colonosim::procedure {

namespace {
static_assert(BleedingMarks::kMaxMarks <= render::kMaxBleedingMarks, "the view draws every mark");

RecorderParameters withColonLength(RecorderParameters p, double length)
{
    p.colonLength = length;
    return p;
}

/// The colon's build options: the adhesions' nodes, validated by name.
physics::ColonBodyOptions colonOptions(const geometry::ColonAnatomy& anatomy,
                                       const ProcedureSettings& settings)
{
    if (settings.adhesions.size() > static_cast<size_t>(ProcedureSettings::kMaxAdhesions)) {
        throw params::ParameterError("adhesions: " + std::to_string(settings.adhesions.size()) +
                                     " adhesions is outside the allowed range [0, " +
                                     std::to_string(ProcedureSettings::kMaxAdhesions) + "]");
    }
    physics::ColonBodyOptions options;
    for (size_t k = 0; k < settings.adhesions.size(); ++k) {
        options.adhesionNodes.push_back(
            wallNodeAt(anatomy, settings.adhesions[k], "adhesions[" + std::to_string(k) + "]"));
    }
    return options;
}

DiscomfortParameters withFailureStrain(DiscomfortParameters p, double strain)
{
    p.mesenteryFailureStrain = strain;
    return p;
}
}  // namespace

ProcedureLoop::ProcedureLoop(const geometry::ColonAnatomy& anatomy, const ProcedureSettings& settings)
    : m_anatomy(anatomy), m_settings(settings),
      m_colon(physics::buildColonBody(anatomy, settings.tissue, settings.environment,
                                      physics::wallCalibrationFor(settings.tissue, settings.calibration),
                                      colonOptions(anatomy, settings))),
      m_scope(settings.scope), m_contact(anatomy, settings.contact),
      m_coupling(settings.contact.contactStiffness, settings.contact.stepLimit, settings.stepping.loopStep,
                 settings.contact.loadRelaxation,
                 {static_cast<int>(std::lround(settings.contact.couplingSweeps)),
                  settings.contact.sweepTolerance, std::lround(settings.contact.prefixSweeps) != 0,
                  std::max(settings.contact.sweepTolerance, settings.contact.passSweepTolerance),
                  static_cast<int>(std::lround(settings.contact.sweepAcceleration))},
                 ContactPoints{1 + static_cast<int>(std::lround(settings.contact.elementPoints))},
                 std::lround(settings.contact.sideNormals) != 0,
                 std::lround(settings.contact.stickingFriction) != 0,
                 std::lround(settings.contact.spinFriction) != 0),
      m_loops(anatomy.centreline, settings.loops),
      m_discomfort(withFailureStrain(settings.discomfort, settings.tissue.mesenteryMaxStrain)),
      m_lesions(anatomy, settings.lesions, settings.viewing), m_bleeding(settings.bleeding),
      m_recorder(withColonLength(settings.recorder, anatomy.centreline.length()))
{
    settings.insufflator.validate();
    // Over one loop step a free wall node under a load held for the step
    // gives way by dt^2 / (2 m) per newton (its springs only hold it back:
    // 1.2-2.1 mm/N measured on the default colon against 2.4 mm/N).
    const double dt = settings.stepping.loopStep;
    m_wallCompliance.resize(m_colon.body.numNodes());
    for (int i = 0; i < m_colon.body.numNodes(); ++i) {
        m_wallCompliance[i] = m_colon.body.isFixed(i) ? 0.0 : 0.5 * dt * dt / m_colon.body.masses()[i];
    }
    // Start at rest in equilibrium under gravity and insufflation (the
    // sleeping of nodes at rest assumes it), with no contact yet.
    m_restSolve = physics::solveStaticEquilibrium(m_colon.body, 1e-5, 1000);
    m_simulation = std::make_unique<physics::TissueSimulation>(m_colon.body, settings.stepping);
    if (settings.activeRegion) {
        m_region = std::make_unique<physics::ActiveRegion>(m_colon.neighbours, physics::SleepParameters{});
        m_simulation->setActiveRegion(m_region.get());
    }
    const geometry::Centreline& c = anatomy.centreline;
    m_scope.setHandlePose(c.points.front(), c.tangents.front(), c.normals.front());
    m_loops.setBendingSection(settings.scope.bendingSectionLength);
    m_loopAnalysisSteps = std::max(
        1, static_cast<int>(std::lround(settings.loops.analysisInterval / settings.stepping.loopStep)));
    m_trace.loopStep = settings.stepping.loopStep;
    m_viewMarks.reserve(BleedingMarks::kMaxMarks);
}

void ProcedureLoop::applyContact()
{
    m_scope.beginStep(m_settings.stepping.loopStep, m_settings.scope.jointDampingRatio);
    const auto nodes = m_scope.nodePositions();
    const auto n = static_cast<Eigen::Index>(nodes.size());
    m_scopePrevious = m_scopeNow;
    m_scopeNow.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i) {
        m_scopeNow.col(i) = nodes[static_cast<size_t>(i)];
    }
    // Nodes are counted from the base; when a node has just passed the anus
    // the previous shape has one node fewer: align the two from the tip.
    m_scopeVelocity.setZero(3, n);
    Eigen::Matrix3Xd& previous = m_scopeAligned;
    previous = m_scopeNow;
    const Eigen::Index shift = n - m_scopePrevious.cols();
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index j = i - shift;
        if (j >= 0 && j < m_scopePrevious.cols()) {
            previous.col(i) = m_scopePrevious.col(j);
            m_scopeVelocity.col(i) = (m_scopeNow.col(i) - previous.col(i)) / m_settings.stepping.loopStep;
        }
    }
    if (std::lround(m_settings.contact.spinFriction) != 0) {
        measureSpin(static_cast<int>(shift));
    }
    // The contact is measured against the wall where its own motion carries
    // it over the step (x + v dt), as the scope's side is measured where the
    // step's loads will put it: against the wall's present position a node
    // still moving away from a load is unloaded the next step and pushed
    // again the one after, and a colon pressed by a still scope kept a
    // load flipping between two values from step to step.
    m_wallAhead = m_colon.body.positions() + m_settings.stepping.loopStep * m_colon.body.velocities();
    // The contact points' velocities hold for every pass of the step.
    m_coupling.points().interpolate(m_scopeVelocity, m_pointVelocity);
    // The coupling's model is linear about the step's start shape; where the
    // chain's nonlinear solve ends elsewhere (a shaft near its buckling load
    // swings further than the model says), the contact is re-measured on the
    // shape the chain found and solved again, until the loads settle. With a
    // looser tolerance for the solves another follows, every pass is run, so
    // that the step's loads come from a solve to the full tolerance.
    const int passes = static_cast<int>(std::lround(m_settings.contact.couplingPasses));
    const bool loosePasses = m_settings.contact.passSweepTolerance > m_settings.contact.sweepTolerance;
    solveContact(m_scopeNow, static_cast<int>(shift), true, passes == 1);
    m_passes = 1;
    while (m_passes < passes) {
        ++m_passes;
        m_passLoads = m_coupling.loads();
        const auto solved = m_scope.nodePositions();
        m_scopePass.resize(3, n);
        for (Eigen::Index i = 0; i < n; ++i) {
            m_scopePass.col(i) = solved[static_cast<size_t>(i)];
        }
        solveContact(m_scopePass, 0, false, m_passes == passes);
        if (!loosePasses && m_passLoads.cols() == m_coupling.loads().cols() &&
            (m_passLoads - m_coupling.loads()).cwiseAbs().maxCoeff() < kPassTolerance) {
            break;
        }
    }
    const std::vector<contact::LumenNodeContact>& contacts = m_contact.contacts();
    m_colon.body.clearExternalForces();
    m_maxWallForce = 0.0;
    for (Eigen::Index i = 0; i < m_coupling.loads().cols(); ++i) {
        const Eigen::Vector3d load = m_coupling.loads().col(i);
        if (load.squaredNorm() == 0.0) {
            continue;
        }
        // The wall carries the opposite load, held over the tissue substeps
        // (it also keeps the nodes it touches awake).
        const contact::LumenNodeContact& c = contacts[static_cast<size_t>(i)];
        for (size_t k = 0; k < 4; ++k) {
            if (c.weights[k] > 0.0) {
                m_colon.body.applyExternalForce(c.wallNodes[k], -c.weights[k] * load);
            }
        }
        m_maxWallForce = std::max(m_maxWallForce, load.norm());
    }
}

void ProcedureLoop::measureSpin(int shift)
{
    // Each node's spin about the shaft's axis over the last step, from its
    // element's frame (the tip's own frame at the tip): the rotation
    // C_before^T C_now about the frame's forward axis, small over 1 ms
    // (its angle from the antisymmetric part, whose sine is within 1.3e-5
    // of the angle, relative, at half a degree a step). Nodes that entered
    // since are taken as not spinning.
    const scope::DiscreteRod& rod = m_scope.rod();
    const int n = rod.numNodes();
    const double dt = m_settings.stepping.loopStep;
    m_nodeSpin.setZero(3, n);
    for (int i = 0; i < n; ++i) {
        const int j = i - shift;
        if (j >= 0 && j < static_cast<int>(m_framePrevious.size())) {
            const Eigen::Matrix3d& now = rod.frame[static_cast<size_t>(i)];
            const Eigen::Matrix3d turn = m_framePrevious[static_cast<size_t>(j)].transpose() * now;
            const double angle = 0.5 * (turn(1, 0) - turn(0, 1));
            m_nodeSpin.col(i) = (angle / dt) * now.col(2);
        }
    }
    m_framePrevious.assign(rod.frame.begin(), rod.frame.end());
    m_coupling.points().interpolate(m_nodeSpin, m_pointSpin);
}

void ProcedureLoop::solveContact(const Eigen::Matrix3Xd& scope, int addedAtBase, bool wallMoved,
                                 bool lastSolve)
{
    const ContactPoints& points = m_coupling.points();
    points.interpolate(scope, m_points);
    const auto& contacts =
        m_contact.compute(m_points, m_pointVelocity, 0.5 * m_settings.scope.outerDiameter, m_wallAhead,
                          m_colon.body.velocities(), addedAtBase * points.stride, wallMoved);
    if (std::lround(m_settings.contact.spinFriction) != 0) {
        m_contact.addSurfaceSpin(m_pointSpin);
    }
    m_scope.clearLoads();
    m_scope.addGravity(m_settings.environment.gravity *
                       physics::downDirection(m_settings.environment.patientPosition));
    m_coupling.update(contacts, m_scope.rod(), addedAtBase, m_wallCompliance, wallMoved);
    m_coupling.solveAndApply(m_scope.rod(), m_contact, lastSolve);
    m_scope.step();
}

const ProcedureOutputs& ProcedureLoop::step(const InputSample& input, HandleLoadSink* early)
{
    const std::string rejection = validateInput(input);
    if (rejection.empty()) {
        m_input = quantizeInput(input);
        m_trace.samples.push_back(m_input);
    } else {
        m_trace.samples.push_back(input);  // the raw refused sample: replay refuses it again
    }
    m_frame = ProcedureFrame{};
    m_frame.inputRejected = !rejection.empty();
    m_frame.inputRejection = rejection;

    const double dt = m_settings.stepping.loopStep;
    m_scope.setInsertion(std::min(m_input.insertion, m_settings.scope.workingLength));
    m_scope.setShaftRotation(m_input.rotation);
    m_scope.setDials(m_input.dialUpDown, m_input.dialLeftRight);
    if (m_colon.insufflation != nullptr && (m_input.buttons & (kAir | kSuction)) != 0) {
        const double rate = (m_input.buttons & kAir) != 0 ? m_settings.insufflator.pressureRate
                                                          : -m_settings.insufflator.pressureRate;
        m_colon.insufflation->setPressure(std::clamp(m_colon.insufflation->pressure() + rate * dt, 0.0,
                                                     m_settings.insufflator.maxPressure));
    }

    applyContact();  // contact is resolved inside the scope's chain iterations
    // The handle load is the scope's: known now, before the colon's substeps.
    const scope::HandleLoad load = m_scope.handleLoad();
    m_outputs.handleForce = -load.axialForce;
    m_outputs.handleTorque = load.axialTorque;
    if (early != nullptr) {
        early->handleLoadReady(m_outputs.handleForce, m_outputs.handleTorque);
    }
    m_simulation->advance();
    m_time += dt;
    ++m_steps;
    observe();
    m_recorder.record(m_frame);
    updateBleeding();
    return m_outputs;
}

void ProcedureLoop::updateBleeding()
{
    // The wall's load at each scope node in contact: the normal part of the
    // coupling's load on the node, at the contact's wall point at rest.
    const std::vector<contact::LumenNodeContact>& contacts = m_contact.contacts();
    const Eigen::Matrix3Xd& loads = m_coupling.loads();
    const Eigen::Matrix3Xd& rest = m_anatomy.physicsMesh.vertices;
    m_wallLoads.clear();
    for (Eigen::Index i = 0; i < loads.cols() && static_cast<size_t>(i) < contacts.size(); ++i) {
        const contact::LumenNodeContact& c = contacts[static_cast<size_t>(i)];
        const double force = loads.col(i).dot(c.normal);
        if (!(force > 0.0)) {
            continue;
        }
        Eigen::Vector3d point = Eigen::Vector3d::Zero();
        for (size_t k = 0; k < 4; ++k) {
            point += c.weights[k] * rest.col(c.wallNodes[k]);
        }
        m_wallLoads.push_back(WallLoad{point, force});
    }
    const int appeared = m_bleeding.update(m_wallLoads, m_settings.stepping.loopStep, m_time);
    if (m_bleeding.revision() == m_bleedingRevision) {
        return;
    }
    m_bleedingRevision = m_bleeding.revision();
    const std::vector<ContactMark>& marks = m_bleeding.marks();
    m_viewMarks.resize(marks.size());
    for (size_t k = 0; k < marks.size(); ++k) {
        m_viewMarks[k].restPoint = marks[k].restPoint;
        m_viewMarks[k].radius = marks[k].radius;
        m_viewMarks[k].opacity = marks[k].opacity;
    }
    for (int k = 0; k < appeared; ++k) {
        m_recorder.note(m_time, EventKind::ContactBleeding, {});
    }
}

void ProcedureLoop::observe()
{
    const double dt = m_settings.stepping.loopStep;
    const scope::TipPose tip = m_scope.tipPose();
    m_outputs.tip = tip;  // the handle load was set as soon as the scope had it (step())

    ProcedureFrame& f = m_frame;
    f.time = m_time;
    f.input = m_input;
    f.tipPosition = tip.position;
    f.tipDirection = tip.rotation.col(2);
    if (m_steps % m_loopAnalysisSteps == 0) {
        // The nodes' own contact points: every stride-th from the base.
        const auto& stations = m_contact.contacts();
        const auto stride = static_cast<size_t>(m_coupling.points().stride);
        m_nodeArcs.resize(stations.empty() ? 0 : (stations.size() - 1) / stride + 1);
        for (size_t i = 0; i < m_nodeArcs.size(); ++i) {
            m_nodeArcs[i] = m_contact.tube().arcLength(stations[i * stride].station);
        }
        m_loops.update(m_scopeNow, m_input.insertion, m_nodeArcs);
    }
    f.loop = m_loops.current();
    f.tipArcLength = m_loops.signals().tipArcLength;
    const geometry::CentrelineSample at = geometry::sampleCentreline(m_anatomy.centreline, f.tipArcLength);
    f.tipSegment = at.segment;
    f.colonTangentAtTip = at.tangent;

    f.maxWallForce = m_maxWallForce;
    if (!m_contact.contacts().empty()) {
        // The lens is against the wall: the tip pressed on a wall that faces it.
        const contact::LumenNodeContact& tipContact = m_contact.contacts().back();
        if (tipContact.depth >= 0.0 && tipContact.normal.dot(f.tipDirection) < -0.5) {
            f.lensWallDistance = 0.0;
        }
    }
    f.handleForce = m_outputs.handleForce;
    f.handleTorque = m_outputs.handleTorque;
    const physics::Positions& x = m_colon.body.positions();
    const DiscomfortInput pain{m_colon.insufflation != nullptr ? m_colon.insufflation->pressure() : 0.0,
                               m_colon.mesentery->maxStrain(x),
                               m_settings.tissue.wallYoungModulus *
                                   m_colon.springs->maxTensileStrain(x, physics::SpringFamily::Structural)};
    f.mesenteryStrain = pain.mesenteryStrain;
    f.discomfort = m_discomfort.update(pain, dt);
    f.perforation = m_discomfort.perforates(pain);
    f.lesionsInView = m_lesions.inView(x, tip);
}

}  // namespace colonosim::procedure
