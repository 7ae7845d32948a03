#include "simcore/procedure/BleedingMarks.h"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

namespace colonosim::procedure {

namespace {
using B = BleedingParameters;
constexpr std::array<params::Field<B>, 6> kBleedingFields{{
    {&B::forceThresholdSpec, &B::forceThreshold},
    {&B::minDurationSpec, &B::minDuration},
    {&B::saturationForceSpec, &B::saturationForce},
    {&B::minRadiusSpec, &B::minRadius},
    {&B::maxRadiusSpec, &B::maxRadius},
    {&B::releaseTimeSpec, &B::releaseTime},
}};
/// Pending pressures tracked at once; more simultaneous places (more
/// contacts above threshold than a scope has nodes) are ignored.
constexpr size_t kMaxPending = 64;
constexpr double kFirstOpacity = 0.6;
constexpr double kOpacityPerRepeat = 0.2;
}  // namespace

std::span<const params::Field<BleedingParameters>> BleedingParameters::fields()
{
    return kBleedingFields;
}

void BleedingParameters::validate() const
{
    params::validateFields<BleedingParameters>("bleeding", kBleedingFields, *this);
    if (!(saturationForce > forceThreshold)) {
        throw params::ParameterError(
            "bleeding.saturationForce = " + std::to_string(saturationForce) +
            " N must exceed bleeding.forceThreshold = " + std::to_string(forceThreshold) + " N");
    }
    if (!(maxRadius >= minRadius)) {
        throw params::ParameterError("bleeding.maxRadius = " + std::to_string(maxRadius) +
                                     " m must be at least bleeding.minRadius = " + std::to_string(minRadius) +
                                     " m");
    }
}

BleedingMarks::BleedingMarks(const BleedingParameters& parameters) : m_parameters(parameters)
{
    m_parameters.validate();
    m_marks.reserve(kMaxMarks);
    m_pending.reserve(kMaxPending);
}

double BleedingMarks::radiusFor(double force) const
{
    const BleedingParameters& p = m_parameters;
    const double x =
        std::clamp((force - p.forceThreshold) / (p.saturationForce - p.forceThreshold), 0.0, 1.0);
    return p.minRadius + (p.maxRadius - p.minRadius) * x;
}

int BleedingMarks::nearestMark(const Eigen::Vector3d& p) const
{
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < m_marks.size(); ++k) {
        const double d = (m_marks[k].restPoint - p).norm();
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<int>(k);
        }
    }
    return best;
}

bool BleedingMarks::place(Pending& pending, double time)
{
    const double radius = radiusFor(pending.peak);
    const int nearest = nearestMark(pending.restPoint);
    const bool inside =
        nearest >= 0 && (m_marks[static_cast<size_t>(nearest)].restPoint - pending.restPoint).norm() <
                            m_marks[static_cast<size_t>(nearest)].radius;
    if (inside || static_cast<int>(m_marks.size()) >= kMaxMarks) {
        ContactMark& mark = m_marks[static_cast<size_t>(nearest)];
        mark.radius = std::max(mark.radius, radius);
        mark.peakForce = std::max(mark.peakForce, pending.peak);
        mark.opacity = std::min(1.0, mark.opacity + kOpacityPerRepeat);
        pending.mark = nearest;
        return false;
    }
    m_marks.push_back(ContactMark{pending.restPoint, radius, kFirstOpacity, pending.peak, time});
    pending.mark = static_cast<int>(m_marks.size()) - 1;
    return true;
}

int BleedingMarks::update(std::span<const WallLoad> loads, double dt, double time)
{
    const BleedingParameters& p = m_parameters;
    for (Pending& pending : m_pending) {
        pending.touched = false;
    }
    for (const WallLoad& load : loads) {
        if (!(load.normalForce >= p.forceThreshold)) {
            continue;
        }
        Pending* owner = nullptr;
        for (Pending& pending : m_pending) {
            if ((pending.restPoint - load.restPoint).norm() < p.maxRadius) {
                owner = &pending;
                break;
            }
        }
        if (owner == nullptr) {
            if (m_pending.size() >= kMaxPending) {
                continue;
            }
            m_pending.push_back(Pending{load.restPoint, 0.0, 0.0, 0.0, time, -1, false});
            owner = &m_pending.back();
        }
        // The pressure follows its contact as it slides (the strongest load).
        if (!owner->touched || load.normalForce > owner->force) {
            owner->restPoint = load.restPoint;
            owner->force = load.normalForce;
        }
        owner->peak = std::max(owner->peak, load.normalForce);
        owner->touched = true;
    }
    std::erase_if(m_pending, [&](const Pending& pending) {
        return !pending.touched && time - pending.lastLoaded > p.releaseTime + 1e-12;
    });

    int appeared = 0;
    for (Pending& pending : m_pending) {
        if (!pending.touched) {
            continue;
        }
        pending.lastLoaded = time;
        pending.loaded += dt;
        if (pending.mark < 0) {
            if (pending.loaded + 1e-12 >= p.minDuration) {
                appeared += place(pending, time) ? 1 : 0;
                ++m_revision;
            }
        } else if ((m_marks[static_cast<size_t>(pending.mark)].restPoint - pending.restPoint).norm() >
                   m_marks[static_cast<size_t>(pending.mark)].radius) {
            // Slid off its mark while still pressing: the next mark starts here.
            pending.mark = -1;
            pending.loaded = 0.0;
            pending.peak = pending.force;
        } else {
            ContactMark& mark = m_marks[static_cast<size_t>(pending.mark)];
            if (pending.peak > mark.peakForce) {
                mark.peakForce = pending.peak;
                mark.radius = std::max(mark.radius, radiusFor(pending.peak));
                ++m_revision;
            }
        }
    }
    return appeared;
}

}  // namespace colonosim::procedure
