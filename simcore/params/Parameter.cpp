#include "simcore/params/Parameter.h"

#include <cmath>
#include <sstream>

namespace colonosim::params {

namespace {
std::string formatValue(double value)
{
    std::ostringstream out;
    out.precision(6);
    out << value;
    return out.str();
}

std::string unitSuffix(std::string_view unit)
{
    std::string suffix;
    if (unit != "1") {
        suffix.append(" ").append(unit);
    }
    return suffix;
}
}  // namespace

std::string describeRejection(std::string_view group, const ParameterSpec& spec, double value)
{
    std::ostringstream out;
    out << group << '.' << spec.name << " = " << formatValue(value) << unitSuffix(spec.unit);
    if (!std::isfinite(value)) {
        out << " is not a finite number";
    } else {
        out << " is outside the allowed range";
    }
    out << " [" << formatValue(spec.minValue) << ", " << formatValue(spec.maxValue) << ']'
        << unitSuffix(spec.unit) << " (" << spec.help << ')';
    return out.str();
}

void require(std::string_view group, const ParameterSpec& spec, double value)
{
    if (!spec.accepts(value)) {
        throw ParameterError(describeRejection(group, spec, value));
    }
}

std::string markdownTable(std::string_view group, std::span<const ParameterSpec* const> specs)
{
    std::ostringstream out;
    out << "| parameter | unit | default | range | meaning | source |\n";
    out << "| --- | --- | --- | --- | --- | --- |\n";
    for (const ParameterSpec* spec : specs) {
        out << "| `" << group << '.' << spec->name << "` | " << spec->unit << " | "
            << formatValue(spec->defaultValue) << " | " << formatValue(spec->minValue) << " – "
            << formatValue(spec->maxValue) << " | " << spec->help << " | " << spec->source << " |\n";
    }
    return out.str();
}

}  // namespace colonosim::params
