#pragma once
/// \file
/// Loops in the colonoscope's shaft, from its shape relative to the colon,
/// as an endoscopist reads them on magnetic endoscope imaging (Shah et al.,
/// Gut 2000; reference/clinical-assessment.md lists the types), in the
/// insertion tube (the dial-steered bending section is left out):
///   - excess shaft: each scope node is located on the colon centreline (arc
///     length s); in each segment, the shaft length whose nodes lie there
///     minus the colon length they span. Looping stores shaft in a segment.
///   - stored shaft: the shaft inserted up to the base of the bending
///     section minus that node's arc length along the colon at rest. The
///     scope carries the mobile colon with it when it bows it on its
///     mesentery, so a shaft that bows the sigmoid stores no excess in the
///     segment (the colon's path lengthens with it); the shaft is in the
///     patient all the same, and an endoscopist reads it from the insertion
///     length against where the tip is (a pleated colon makes the stored
///     shaft negative). The bending section (setBendingSection()) is left
///     out because a tip hooked or retroflexed by the dials lies behind the
///     shaft's end along the colon, and that is not shaft stored in a loop.
///   - paradoxical motion: insertion advanced against tip advance along the
///     colon over the last window; the clinical warning sign is a tip that
///     stops moving 1:1 with the shaft (ratio above 2).
///   - crossings: self-crossings of the shaft projected on the coronal plane
///     (seen from the front, x left / z up) that the colon's own path at rest
///     does not have at the same place along it (both strands within
///     `crossingMatch` of one of the path's crossings), and the handedness of
///     each: at a crossing the strand nearer the front passes over the
///     other, and the crossing is right-handed when the over strand's
///     direction turns counter-clockwise onto the under strand's in the
///     anterior view (a right-handed helix seen side on crosses itself
///     right-handed). For a loop in the left colon the crossings are read over
///     the whole of the shaft in the rectum, sigmoid and descending colon: an
///     alpha loop closes where the shaft leaves the sigmoid.
/// Each node is located along the colon near its predecessor (a window of
/// -5/+15 cm), so loops never jump to a part of the colon close in space.
/// Classification, by the segment holding the most excess shaft:
///   sigmoid (or descending) with crossings: Alpha if they are right-handed
///     on balance, ReverseAlpha if left-handed. The handedness, not the
///     direction the projection turns, is the loop's: the same clockwise
///     curl in the anterior view is one or the other by which strand passes
///     in front. And the handedness decides the torque that takes the loop
///     out. Turning the handle by an angle a while the shaft beyond is held
///     changes the shaft's link (twist plus writhe, Calugareanu) by the tip's
///     turn less the handle's; clockwise as the operator sees it is a
///     right-handed turn about the insertion direction, so it adds
///     left-handed link, which undoes a right-handed loop's writhe and
///     tightens a left-handed one. reference/clinical-assessment.md: the
///     alpha is a clockwise spiral (seen along the shaft: right-handed) and
///     is reduced by clockwise torque; the reverse alpha needs
///     counter-clockwise torque (clockwise tightens it, with a growing
///     resistance to the turn; the alpha manoeuvre forms an alpha by turning
///     counter-clockwise). The model shows the same: the expert's left-handed
///     loop in the left-swept redundant sigmoid comes undone at 49.9 s
///     turning counter-clockwise, 62.0 s without turning and 64.7 s turning
///     clockwise (build/bench/loop_reduction). The model's crossed loops
///     curl clockwise in the anterior view, so its alpha's distal limb
///     passes behind the shaft and its reverse alpha's in front: the other
///     way round from the reference's "the reverse alpha passes behind the
///     shaft", which holds for loops curling counter-clockwise;
///   sigmoid without a crossing, or with crossings whose handedness cancels: N;
///   transverse (or hepatic flexure): GammaDeepTransverse;
///   splenic flexure with a crossing: ReverseSplenic;
/// and None while both the excess and the stored shaft are below the
/// threshold. A loop read from the stored shaft alone is placed in the
/// segment with the most excess (the sigmoid's N loop when the shaft bows a
/// colon that moves with it).
/// Hysteresis: a loop forms above the threshold and resolves below
/// `resolveFraction` of it; once formed, its type changes only when another
/// type has been read for `typeDwell` (a shaft on the border of two segments, or
/// with a crossing that comes and goes, would otherwise flicker between
/// types from one analysis to the next, and each flicker would be a new loop
/// event in the recording).

#include "simcore/geometry/Centreline.h"
#include "simcore/params/Parameter.h"

#include <Eigen/Core>

#include <algorithm>
#include <span>
#include <string_view>
#include <vector>

namespace colonosim::procedure {

enum class LoopKind { None, N, Alpha, ReverseAlpha, GammaDeepTransverse, ReverseSplenic };

[[nodiscard]] std::string_view loopName(LoopKind kind);

/// The loop detector's declared parameters (`colonosim params`).
struct LoopParameters {
    using Spec = params::ParameterSpec;
    static constexpr Spec thresholdSpec{
        "threshold",
        "m",
        0.08,
        0.02,
        0.30,
        "excess shaft in one segment, or shaft stored ahead of the bending section, that makes a loop",
        "assumption: no published length; six outer diameters of the 13 mm scope, above the shaft a "
        "straight insertion stores as the colon gives way (3.0 cm when the hooked hard case begins "
        "to push), below the 9.2 cm that push stores"};
    static constexpr Spec resolveFractionSpec{
        "resolveFraction",
        "1",
        0.6,
        0.1,
        0.95,
        "fraction of the threshold below which a formed loop is resolved",
        "model choice: hysteresis, so that a loop held at the threshold does not form and resolve "
        "from one analysis to the next"};
    static constexpr Spec typeDwellSpec{
        "typeDwell",
        "s",
        0.2,
        0.01,
        5.0,
        "time another type must be read without a break before a formed loop takes it",
        "model choice: shorter than any real change of loop, longer than a flicker of a shaft on the "
        "border of two segments"};
    static constexpr Spec analysisIntervalSpec{"analysisInterval",
                                               "s",
                                               0.01,
                                               0.001,
                                               0.1,
                                               "time between two analyses of the shaft's shape",
                                               "model choice: the recorder's 100 Hz sampling rate"};
    static constexpr Spec crossingMatchSpec{
        "crossingMatch",
        "m",
        0.10,
        0.01,
        0.50,
        "how far along the colon both strands of a shaft crossing may lie from a crossing of the colon's "
        "own path at rest for it to be the colon's, not a loop's",
        "model choice: a shaft that follows a colon which crosses itself at rest crosses where the colon "
        "does, give or take how far the mobile colon moves with it (its sigmoid's rings 5-10 cm under the "
        "expert, README)"};
    static constexpr Spec paradoxWindowSpec{
        "paradoxWindow",
        "m",
        0.02,
        0.005,
        0.2,
        "insertion over which the tip's advance is compared with the shaft's",
        "reference/clinical-assessment.md: the warning sign is a tip that stops moving 1:1 with the "
        "shaft; 2 cm, a push an endoscopist feels as one"};

    double threshold = thresholdSpec.defaultValue;
    double resolveFraction = resolveFractionSpec.defaultValue;
    double typeDwell = typeDwellSpec.defaultValue;
    double analysisInterval = analysisIntervalSpec.defaultValue;
    double paradoxWindow = paradoxWindowSpec.defaultValue;
    double crossingMatch = crossingMatchSpec.defaultValue;

    [[nodiscard]] static std::span<const params::Field<LoopParameters>> fields();
    /// Throws ParameterError naming the field, the value and the range.
    void validate() const;
    /// Analyses in a row that make up `typeDwell` (at least 1).
    [[nodiscard]] int typeDwellAnalyses() const;
};

struct LoopSignals {
    double excessShaft = 0.0;  ///< in the worst segment, m
    /// Shaft inserted up to the base of the bending section minus that node's
    /// arc length along the colon at rest, m.
    double storedShaft = 0.0;
    geometry::Segment segment = geometry::Segment::Rectum;  ///< where the excess is
    /// Coronal self-crossings of the looped shaft that the colon's path at rest does not have.
    int crossings = 0;
    /// Their handedness summed: +1 for each right-handed crossing, -1 for each left-handed.
    int handedness = 0;
    /// Coronal self-crossings of the looped shaft where the colon's path at rest
    /// crosses itself too (a sigmoid curled into an alpha or reverse alpha at
    /// rest, the shaft following it), and their handedness summed. A loop
    /// with no crossing of its own is typed by these: the shaft's shape is
    /// what shape imaging shows and what sets the way to turn it out.
    int sharedCrossings = 0;
    int sharedHandedness = 0;
    /// Signed coronal turning of the looped shaft beyond the colon's path over
    /// the same stretch, rad (+ = counter-clockwise); reported, not used to type a loop.
    double turning = 0.0;
    double tipAdvanceRatio = 1.0;       ///< insertion advance / tip advance over the window (1 = 1:1)
    double tipArcLength = 0.0;          ///< where the tip is along the colon, m
    LoopKind reading = LoopKind::None;  ///< this analysis's own type, before the type's hysteresis
};

class LoopDetector {
public:
    /// Throws ParameterError for a parameter outside its declared range.
    explicit LoopDetector(const geometry::Centreline& colon, const LoopParameters& parameters = {});

    /// The length of the tip's bending section, m (default 0): loops are read
    /// in the insertion tube, the nodes up to the first at least this far
    /// behind the tip, and the stored shaft is measured at that node.
    void setBendingSection(double length) { m_bendingSection = std::max(0.0, length); }

    /// Analyses the shaft (inserted nodes, anus to tip) at insertion length
    /// `insertion` (m). Call every LoopParameters::analysisInterval.
    LoopKind update(const Eigen::Matrix3Xd& shaft, double insertion, std::span<const double> nodeArcs = {});

    [[nodiscard]] LoopKind current() const { return m_current; }
    [[nodiscard]] const geometry::Centreline& colon() const { return m_colon; }
    [[nodiscard]] const LoopSignals& signals() const { return m_signals; }
    [[nodiscard]] const LoopParameters& parameters() const { return m_parameters; }

    /// Arc length along the colon of the centreline point nearest to p, m.
    [[nodiscard]] double locate(const Eigen::Vector3d& p) const;
    /// The same, searching only arc lengths in [from, to].
    [[nodiscard]] double locateNear(const Eigen::Vector3d& p, double from, double to) const;

private:
    static constexpr double kBackWindow = 0.05;  ///< m a node may lie behind its predecessor along the colon
    static constexpr double kForwardWindow = 0.15;  ///< m it may lie ahead

    /// The type the signals of one analysis read as (the excess is above the threshold).
    [[nodiscard]] static LoopKind classify(const LoopSignals& signals);
    /// The centreline between two arc lengths, every centimetre.
    [[nodiscard]] Eigen::Matrix3Xd colonPath(double from, double to) const;

    const geometry::Centreline& m_colon;
    LoopParameters m_parameters;
    int m_typeDwell = 1;            ///< analyses (LoopParameters::typeDwellAnalyses())
    double m_bendingSection = 0.0;  ///< m
    LoopKind m_current = LoopKind::None;
    LoopKind m_pending = LoopKind::None;  ///< a type read instead of the current one
    int m_pendingReads = 0;               ///< analyses in a row it has been read
    LoopSignals m_signals;
    double m_windowInsertion = 0.0;
    double m_windowTip = 0.0;
};

/// One self-crossing of a polyline projected on the coronal (x, z) plane.
struct CoronalCrossing {
    double first = 0.0;   ///< where the earlier strand crosses: node index plus the fraction of its segment
    double second = 0.0;  ///< where the later strand crosses, the same way
    /// +1 right-handed, -1 left-handed: the strand nearer the front (smaller
    /// y) passes over, and the crossing is right-handed when the over
    /// strand's direction turns counter-clockwise onto the under strand's in
    /// the anterior view.
    int handedness = 0;
};

/// Self-crossings of a polyline projected on the coronal (x, z) plane, in order.
[[nodiscard]] std::vector<CoronalCrossing> coronalCrossingList(const Eigen::Matrix3Xd& polyline);
/// Their number.
[[nodiscard]] int coronalCrossings(const Eigen::Matrix3Xd& polyline);
/// Signed turning of a polyline in the coronal plane (anterior view), rad.
[[nodiscard]] double coronalTurning(const Eigen::Matrix3Xd& polyline);

}  // namespace colonosim::procedure
