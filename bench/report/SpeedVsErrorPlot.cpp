#include "bench/report/SpeedVsErrorPlot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

namespace colonosim::bench {

namespace {
constexpr double kWidth = 820.0;
constexpr double kHeight = 560.0;
constexpr double kLeft = 90.0;
constexpr double kRight = 220.0;  // room for the legend
constexpr double kTop = 50.0;
constexpr double kBottom = 70.0;
constexpr const char* kColours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e"};

struct Range {
    double lo = std::numeric_limits<double>::infinity();
    double hi = 0.0;
    void add(double value)
    {
        if (std::isfinite(value) && value > 0.0) {
            lo = std::min(lo, value);
            hi = std::max(hi, value);
        }
    }
    /// Whole decades around the data.
    void snap()
    {
        if (!(hi > 0.0)) {
            lo = 1.0;
            hi = 10.0;
        }
        lo = std::pow(10.0, std::floor(std::log10(lo)));
        hi = std::pow(10.0, std::ceil(std::log10(hi)));
        if (hi <= lo) {
            hi = lo * 10.0;
        }
    }
};

std::string decadeLabel(int exponent)
{
    std::ostringstream label;
    label << "1e" << exponent;
    return label.str();
}
}  // namespace

void writeSpeedVsErrorSvg(const std::vector<SweepRow>& rows, const PeerPoint& peer, const std::string& title,
                          std::ostream& out)
{
    Range xr;
    Range yr;
    for (const SweepRow& row : rows) {
        xr.add(row.cpuPerSimulatedSecond);
        if (row.stable) {
            yr.add(row.rmsError);
        }
    }
    xr.add(peer.cpuPerSimulatedSecond);
    yr.add(peer.rmsError);
    xr.snap();
    yr.snap();
    const double plotW = kWidth - kLeft - kRight;
    const double plotH = kHeight - kTop - kBottom;
    const auto px = [&](double x) {
        return kLeft + plotW * std::log10(x / xr.lo) / std::log10(xr.hi / xr.lo);
    };
    const auto py = [&](double y) {
        return kTop + plotH * (1.0 - std::log10(y / yr.lo) / std::log10(yr.hi / yr.lo));
    };

    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
        << "\" font-family=\"sans-serif\" font-size=\"13\">\n";
    out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    out << "<text x=\"" << kLeft + plotW / 2 << "\" y=\"28\" text-anchor=\"middle\" font-size=\"16\">"
        << title << "</text>\n";
    out << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << plotW << "\" height=\"" << plotH
        << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (int e = static_cast<int>(std::lround(std::log10(xr.lo))); e <= std::lround(std::log10(xr.hi)); ++e) {
        const double x = px(std::pow(10.0, e));
        out << "<line x1=\"" << x << "\" y1=\"" << kTop << "\" x2=\"" << x << "\" y2=\"" << kTop + plotH
            << "\" stroke=\"#ddd\"/>\n";
        out << "<text x=\"" << x << "\" y=\"" << kTop + plotH + 18 << "\" text-anchor=\"middle\">"
            << decadeLabel(e) << "</text>\n";
    }
    for (int e = static_cast<int>(std::lround(std::log10(yr.lo))); e <= std::lround(std::log10(yr.hi)); ++e) {
        const double y = py(std::pow(10.0, e));
        out << "<line x1=\"" << kLeft << "\" y1=\"" << y << "\" x2=\"" << kLeft + plotW << "\" y2=\"" << y
            << "\" stroke=\"#ddd\"/>\n";
        out << "<text x=\"" << kLeft - 8 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">" << decadeLabel(e)
            << "</text>\n";
    }
    out << "<text x=\"" << kLeft + plotW / 2 << "\" y=\"" << kHeight - 22
        << "\" text-anchor=\"middle\">CPU seconds per simulated second (log)</text>\n";
    out << "<text transform=\"translate(24," << kTop + plotH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">rms node error vs reference, m (log)</text>\n";

    std::map<std::string, std::vector<const SweepRow*>> series;
    std::vector<std::string> order;
    for (const SweepRow& row : rows) {
        if (series.find(row.integrator) == series.end()) {
            order.push_back(row.integrator);
        }
        series[row.integrator].push_back(&row);
    }
    double legendY = kTop + 10;
    const double legendX = kLeft + plotW + 20;
    for (size_t s = 0; s < order.size(); ++s) {
        const char* colour = kColours[s % 4];
        std::vector<const SweepRow*> points = series[order[s]];
        std::sort(points.begin(), points.end(),
                  [](const SweepRow* a, const SweepRow* b) { return a->step > b->step; });
        std::ostringstream line;
        for (const SweepRow* row : points) {
            if (row->stable && row->rmsError > 0.0) {
                line << px(row->cpuPerSimulatedSecond) << ',' << py(row->rmsError) << ' ';
            }
        }
        out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\""
            << line.str() << "\"/>\n";
        for (const SweepRow* row : points) {
            if (row->stable && row->rmsError > 0.0) {
                out << "<circle cx=\"" << px(row->cpuPerSimulatedSecond) << "\" cy=\"" << py(row->rmsError)
                    << "\" r=\"4\" fill=\"" << colour << "\"/>\n";
            } else if (!row->stable && row->cpuPerSimulatedSecond > 0.0) {
                const double x = px(row->cpuPerSimulatedSecond);
                out << "<path d=\"M" << x - 6 << ',' << kTop - 6 << " l12,12 m0,-12 l-12,12\" stroke=\""
                    << colour << "\" stroke-width=\"2.5\"/>\n";
            }
        }
        out << "<line x1=\"" << legendX << "\" y1=\"" << legendY << "\" x2=\"" << legendX + 24 << "\" y2=\""
            << legendY << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n";
        out << "<circle cx=\"" << legendX + 12 << "\" cy=\"" << legendY << "\" r=\"4\" fill=\"" << colour
            << "\"/>\n";
        out << "<text x=\"" << legendX + 32 << "\" y=\"" << legendY + 4 << "\">" << order[s] << "</text>\n";
        legendY += 22;
    }
    if (peer.cpuPerSimulatedSecond > 0.0 && peer.rmsError > 0.0) {
        const double x = px(peer.cpuPerSimulatedSecond);
        const double y = py(peer.rmsError);
        out << "<rect x=\"" << x - 6 << "\" y=\"" << y - 6 << "\" width=\"12\" height=\"12\" fill=\""
            << kColours[4] << "\" stroke=\"black\"/>\n";
    }
    out << "<rect x=\"" << legendX + 6 << "\" y=\"" << legendY - 6 << "\" width=\"12\" height=\"12\" fill=\""
        << kColours[4] << "\" stroke=\"black\"/>\n";
    out << "<text x=\"" << legendX + 32 << "\" y=\"" << legendY + 4 << "\">" << peer.name
        << " (1 ms)</text>\n";
    legendY += 22;
    out << "<path d=\"M" << legendX + 6 << ',' << legendY - 6 << " l12,12 m0,-12 l-12,12\" stroke=\"black\" "
        << "stroke-width=\"2.5\"/>\n";
    out << "<text x=\"" << legendX + 32 << "\" y=\"" << legendY + 4 << "\">unstable (on top edge)</text>\n";
    out << "</svg>\n";
}

}  // namespace colonosim::bench
