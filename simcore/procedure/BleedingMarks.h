#pragma once
/// \file
/// Contact bleeding marks: where the scope presses the mucosa hard enough for
/// long enough, a small submucosal haemorrhage (a petechial spot) appears at
/// that place of the wall and stays for the rest of the session.
///
/// Input, each loop step: the wall loads of that step, one per contact, as a
/// rest-configuration wall point and the normal force the scope puts on the
/// wall there (N). Nothing here depends on the contact algorithm.
///
/// Model (every constant in BleedingParameters):
///   - a load F >= F_t (forceThreshold) starts or continues a pending
///     pressure; loads within maxRadius of a pending pressure's place belong
///     to it, and the place follows the strongest of them (the contact
///     slides while it presses: at 0.5 m/s at most 0.5 mm per 1 ms step). A
///     pending pressure that receives no such load for longer than
///     releaseTime is forgotten: the pressure must be continuous, up to the
///     contact's chatter; only loaded steps count towards minDuration.
///   - once a pending place has been loaded for minDuration, a mark appears
///     there with radius
///         R(F) = R_min + (R_max - R_min) clamp((F - F_t) / (F_s - F_t), 0, 1),
///     F the peak force of the pending pressure (F_s saturationForce), and
///     opacity 0.6. While the same pressure goes on, a larger peak grows the
///     mark's radius; once it has slid beyond the mark's radius it counts
///     again from zero, so a long hard slide leaves a trail of marks.
///   - a new mark whose place lies within an existing mark's radius
///     strengthens that mark instead (radius max(R, R(F)), opacity + 0.2 up
///     to 1). At kMaxMarks marks, a new one strengthens the nearest mark.
/// Deterministic; the storage is reserved once (kMaxMarks marks and pending
/// places), so a step allocates nothing.
///
/// Forces, not pressures: the threshold is a force at one scope node. With
/// the 13 mm tip's contact patch of about 1 cm^2, F_t = 1 N is a mean
/// pressure of 10 kPa (75 mmHg), over twice the mucosal capillary perfusion
/// pressure (~4 kPa): the mucosa under it is blanched and crushed, not
/// merely touched. No measured threshold for scope-induced mucosal
/// haemorrhage exists; see BleedingParameters for the assumption.

#include "simcore/params/Parameter.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace colonosim::procedure {

struct BleedingParameters {
    using Spec = params::ParameterSpec;
    static constexpr Spec forceThresholdSpec{
        "forceThreshold",
        "N",
        1.0,
        0.1,
        50.0,
        "normal force of the scope on the wall at one contact above which the mucosa is traumatised",
        "assumption: no measured threshold; 1 N over the ~1 cm^2 patch of a 13 mm tip is ~10 kPa "
        "(75 mmHg), over twice the mucosal capillary perfusion pressure; a node load this large is "
        "reached only when the tip is driven into the wall (the scope's lateral stiffness is 12-160 N/m)"};
    static constexpr Spec minDurationSpec{
        "minDuration",
        "s",
        0.1,
        0.0,
        10.0,
        "time the threshold must be exceeded without a break by one (possibly sliding) contact for a mark",
        "assumption: a brush of the wall (tens of ms) does not bruise; sustained pressing does"};
    static constexpr Spec saturationForceSpec{"saturationForce",
                                              "N",
                                              5.0,
                                              0.2,
                                              100.0,
                                              "normal force at which a mark reaches its largest radius",
                                              "assumption: five times the threshold, a third of the "
                                              "recorder's 15 N excessive handle force (Appleyard et al. "
                                              "2000)"};
    static constexpr Spec minRadiusSpec{"minRadius",
                                        "m",
                                        1.0e-3,
                                        0.2e-3,
                                        5.0e-3,
                                        "radius of a mark made at the threshold force",
                                        "petechiae: 1-2 mm pinpoint haemorrhages"};
    static constexpr Spec maxRadiusSpec{"maxRadius",
                                        "m",
                                        3.0e-3,
                                        0.5e-3,
                                        10.0e-3,
                                        "largest radius of a mark",
                                        "assumption: a submucosal haemorrhage the size of the tip's "
                                        "rim contact, about half the 13 mm tip"};

    static constexpr Spec releaseTimeSpec{
        "releaseTime",
        "s",
        0.02,
        0.0,
        1.0,
        "a break in the load shorter than this does not end a pressure",
        "model choice: the penalty contact of a pressing tip chatters on and off over a few 1 ms loop steps"};

    double forceThreshold = forceThresholdSpec.defaultValue;
    double minDuration = minDurationSpec.defaultValue;
    double saturationForce = saturationForceSpec.defaultValue;
    double minRadius = minRadiusSpec.defaultValue;
    double maxRadius = maxRadiusSpec.defaultValue;
    double releaseTime = releaseTimeSpec.defaultValue;

    [[nodiscard]] static std::span<const params::Field<BleedingParameters>> fields();
    /// Throws ParameterError naming the field, the value and the range; also
    /// when saturationForce <= forceThreshold or maxRadius < minRadius.
    void validate() const;
};

/// The scope's normal force on the wall at one contact.
struct WallLoad {
    Eigen::Vector3d restPoint = Eigen::Vector3d::Zero();  ///< the wall point at rest, m
    double normalForce = 0.0;                             ///< N, >= 0
};

struct ContactMark {
    Eigen::Vector3d restPoint = Eigen::Vector3d::Zero();  ///< m
    double radius = 0.0;                                  ///< m
    double opacity = 0.0;                                 ///< 0..1
    double peakForce = 0.0;                               ///< N
    double onset = 0.0;                                   ///< s, when it appeared
};

class BleedingMarks {
public:
    static constexpr int kMaxMarks = 64;

    /// Throws ParameterError for invalid parameters.
    explicit BleedingMarks(const BleedingParameters& parameters);

    /// One loop step of `dt` seconds ending at `time`. Returns the number of
    /// marks that appeared (0 when the marks only grew or nothing changed).
    int update(std::span<const WallLoad> loads, double dt, double time);

    [[nodiscard]] const std::vector<ContactMark>& marks() const { return m_marks; }
    /// Counts every change of the marks (new, grown, strengthened).
    [[nodiscard]] long revision() const { return m_revision; }
    /// R(F) of the model, m.
    [[nodiscard]] double radiusFor(double force) const;

private:
    struct Pending {
        Eigen::Vector3d restPoint;
        double force = 0.0;       ///< N, this step's strongest load
        double loaded = 0.0;      ///< s above threshold so far
        double lastLoaded = 0.0;  ///< s, the last step with a load
        double peak = 0.0;        ///< N
        int mark = -1;            ///< the mark this pressure made, once it has
        bool touched = false;
    };
    bool place(Pending& pending, double time);
    [[nodiscard]] int nearestMark(const Eigen::Vector3d& p) const;

    BleedingParameters m_parameters;
    std::vector<ContactMark> m_marks;
    std::vector<Pending> m_pending;
    long m_revision = 0;
};

}  // namespace colonosim::procedure
