#pragma once
/// \file
/// Scripted operators (autopilots) for tests, benchmarks and the demo. They
/// act only through the InputSample a person's hands produce, and see only
/// what a person would: the handle force, the tip's view of the lumen, and
/// the loop warning signs (a tip that stops moving with the shaft).
///   Expert: inserts at 3 cm/s steering the tip towards the lumen with the
///     dials, handing left/right deflection over to the up/down dial by
///     shaft torque (torque steering), and feeds only while the lumen is
///     centred; when the handle force it feels (smoothed over 0.1 s)
///     exceeds 8 N (12 N once its tip has reached the descending colon),
///     or the shaft stores a loop and the tip has stopped
///     following it (insertion over tip advance above 2, the clinical
///     warning sign; a loop the tip still advances through is let be),
///     straightens the tip and withdraws with clockwise torque (the standard
///     loop reduction; counter-clockwise while the loop is read as a reverse
///     alpha, which clockwise torque tightens) 3 cm and on until the loop is
///     out, 15 cm at most,
///     before going on, drawing the shaft back only while the pull it feels
///     stays under its force limit (above it the hand holds, the turn going
///     on, and after 3 s gives the back-off up and goes on in); when a loop comes back at the same place
///     after two reductions (a redundant colon that reloops whatever is done), lets it form and pushes on
///     through it, the tip aimed, until the tip is 15 cm further along the colon, and reduces it from there,
///     the tip hooked beyond the loop; aims a lumen that lies behind the folded tip by more bend towards it;
///     when a dial is at its stop and the scope no longer gets on, pulls back 4 cm and re-approaches, and if
///     that fails at the same bend slides by it (1 cm/s under 3 N, tip deflected towards the lumen, up to 6
///     cm) before pulling back again; from the cecum withdraws slowly (1 cm/s), sweeping the tip; marks a
///     lesion that has stayed in view for 0.5 s.
///   Novice: pushes at 6 cm/s through resistance, backs off only above
///     25 N, steers late (low gain), and withdraws fast (4 cm/s).
///   Replay: plays an input trace back sample by sample.

#include "simcore/procedure/InputTrace.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>

namespace colonosim::procedure {

class Operator {
public:
    virtual ~Operator() = default;
    /// The next input, from what the loop showed after its last step.
    virtual InputSample next(const ProcedureLoop& loop) = 0;
    /// True when the operator has finished (withdrawn, or the trace ended).
    [[nodiscard]] virtual bool finished() const = 0;
    /// True when next() itself keeps the session in real time (a device that
    /// sends its frames at its own rate): a loop driven by it adds no
    /// wall-clock pacing of its own. Scripted and replayed input has no
    /// clock: the host paces it, or runs it as fast as it can.
    [[nodiscard]] virtual bool keepsTime() const { return false; }
};

struct OperatorStyle {
    double insertSpeed;    ///< m/s
    double withdrawSpeed;  ///< m/s after the cecum
    double forceLimit;     ///< N of handle force that makes it back off
    /// N of handle force that makes it back off once its tip has reached the
    /// descending colon, the shaft lying through the sigmoid (see expertStyle()).
    double pastSigmoidForceLimit;
    bool reducesLoops;    ///< withdraws with clockwise torque when a loop forms
    double steeringGain;  ///< 1/s: rate at which the dials follow the lumen's angular offset
    double markDelay;     ///< s a lesion stays in view before it is marked (recognition time)
    /// Steer, then push: the dials integrate the lumen's offset and hold where
    /// it is centred, and the scope is fed only while the lumen lies within
    /// kAimedWithin of the view's centre (the expert); otherwise the dials
    /// follow the offset and the feed never waits (the novice).
    bool aimsBeforeInserting = false;
    /// s: time constant of the handle force as the hand feels it (the expert
    /// reacts to a push that lasts, not to a millisecond's jolt of the
    /// contact); 0: reacts to the instantaneous force (the novice).
    double feelTime = 0.0;
    /// rad/s: how fast a loop reducer turns the shaft while withdrawing from
    /// a loop (the way reductionTurn() says); 0 withdraws without turning.
    double reductionTurnRate = 0.5;
    /// Backing off (a loop reduction, a pull-back), the shaft is drawn back
    /// only while the pull the hand feels stays under the force limit; above
    /// it the hand holds (the turn goes on), and after kPullHeldFor of that
    /// gives the back-off up (the expert). false: pulls whatever it takes (the novice).
    bool limitsPull = false;
};

/// Angular offset of the lumen from the view's centre within which an
/// operator that aims before inserting feeds the scope, rad.
inline constexpr double kAimedWithin = 0.35;

/// The way a loop reducer turns the shaft while withdrawing from a loop of
/// `kind`, seen from the operator: -1 clockwise (the standard reduction), +1
/// counter-clockwise for a reverse alpha (reference/clinical-assessment.md).
[[nodiscard]] double reductionTurn(LoopKind kind);

[[nodiscard]] OperatorStyle expertStyle();
[[nodiscard]] OperatorStyle noviceStyle();

/// The expert's count of loop reductions at one place along the colon:
/// after `perPlace` reductions begun within `samePlace` of each other, the
/// loop read there next is let be, and the scope pushed on through it, until
/// the tip is `passLength` further along the colon (Operator.cpp,
/// kReductionsPerPlace). Distances in m along the colon at rest.
class LoopReductionCount {
public:
    LoopReductionCount(int perPlace, double samePlace, double passLength)
        : m_perPlace(perPlace), m_samePlace(samePlace), m_passLength(passLength)
    {}
    /// True while the tip, at `tipArc`, is passing through a loop it lets be.
    [[nodiscard]] bool passing(double tipArc) const { return tipArc < m_passUntil; }
    /// A loop asks to be reduced with the tip at `tipArc`: true to reduce it;
    /// false to let it be (passing() then holds until the tip is passLength on).
    bool reduceAt(double tipArc);

private:
    int m_perPlace;
    double m_samePlace;
    double m_passLength;
    double m_reducedAt = -1.0;  ///< where the tip was when the first reduction here began, m; < 0: none
    int m_here = 0;             ///< reductions begun there
    double m_passUntil = -1.0;  ///< m along the colon
};

class ScriptedOperator final : public Operator {
public:
    explicit ScriptedOperator(const OperatorStyle& style);
    InputSample next(const ProcedureLoop& loop) override;
    [[nodiscard]] bool finished() const override { return m_finished; }

private:
    /// Insert: aim, then feed. ReduceLoop: back off with clockwise torque.
    /// PullBack / SlideBy: the expert's ways past a bend the dials cannot
    /// aim through (see Operator.cpp). Withdraw: from the cecum out.
    enum class Phase { Insert, ReduceLoop, PullBack, SlideBy, Withdraw };
    /// Enters `phase` (ReduceLoop or PullBack), withdrawing `length` metres.
    void backOffBy(Phase phase, double length);
    /// Relaxes both dials by `fraction` of their deflection; true once the
    /// tip is unhooked (both dials under kUnhooked).
    bool letDialsGo(double fraction);
    /// Backing off with the hand feeling `force` (N, + resisting insertion)
    /// against `limit` at time `now`: true while the pull is held (the shaft
    /// not drawn back this step); gives the back-off up (Insert) once it has
    /// been held kPullHeldFor. Always false for a style that does not limit its pull.
    bool holdPull(double force, double limit, double now);
    OperatorStyle m_style;
    Phase m_phase = Phase::Insert;
    double m_feltForce = 0.0;  ///< the handle force as the hand feels it (smoothed), N
    double m_offCentre = 0.0;  ///< the lumen's angular offset in the view, rad
    InputSample m_input;
    double m_reduceUntil = 0.0;     ///< insertion at which a loop reduction (or a pull-back) ends, m
    double m_reduceFloor = 0.0;     ///< insertion at which a loop reduction ends even with the loop there, m
    bool m_pastSigmoid = false;     ///< the tip has been in the descending colon or beyond
    double m_blockedSince = -1.0;   ///< s: since when a dial is at its stop with no headway; < 0: not
    double m_blockedAt = 0.0;       ///< insertion then, m
    double m_stillSince = -1.0;     ///< s: since when the scope has not been fed kBlockedFeed; < 0: not
    double m_stillAt = 0.0;         ///< insertion then, m
    int m_pullBacks = 0;            ///< pull-backs tried at the present bend
    double m_pullHeldSince = -1.0;  ///< s: since when a back-off has held its pull; < 0: not
    LoopReductionCount m_reductions;  ///< loop reductions at one place, and the loop let be
    double m_bendArc = -1.0;          ///< where along the colon the tip was blocked, m
    double m_slideUntil = 0.0;        ///< insertion at which a slide-by gives up, m
    bool m_finished = false;
    std::array<double, 32> m_inViewSince{};  ///< s, per lesion; negative while out of view
    std::uint32_t m_marked = 0;              ///< lesions already marked
};

class ReplayOperator final : public Operator {
public:
    explicit ReplayOperator(InputTrace trace) : m_trace(std::move(trace)) {}
    InputSample next(const ProcedureLoop& loop) override;
    [[nodiscard]] bool finished() const override { return m_next >= m_trace.samples.size(); }

private:
    InputTrace m_trace;
    size_t m_next = 0;
};

/// "expert", "novice" or "replay:TRACE"; throws ParameterError otherwise.
[[nodiscard]] std::unique_ptr<Operator> makeOperator(std::string_view name);

}  // namespace colonosim::procedure
