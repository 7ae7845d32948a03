#pragma once
/// \file
/// The speed-versus-error figure as a hand-written SVG: log-log axes, error
/// (rms node distance to the reference, m) against cost (CPU seconds per
/// simulated second), one polyline series per integrator ordered by step,
/// the peer as a single marker, decade ticks with labels, a legend, and runs
/// that went unstable drawn as crosses on the top edge.

#include "bench/report/SpeedErrorSweep.h"

#include <iosfwd>
#include <string>

namespace colonosim::bench {

struct PeerPoint {
    std::string name;
    double cpuPerSimulatedSecond = 0.0;
    double rmsError = 0.0;  ///< m
};

void writeSpeedVsErrorSvg(const std::vector<SweepRow>& rows, const PeerPoint& peer, const std::string& title,
                          std::ostream& out);

}  // namespace colonosim::bench
