#pragma once
/// \file
/// Declared physical parameters, in the spirit of SOFA's declared data.
///
/// Every physical parameter is declared exactly once, as a constexpr
/// ParameterSpec carrying its name, SI unit, default, valid range, one-line
/// help and source. The same declaration initialises the struct member,
/// drives validation messages, reading from files and the documentation
/// table (`colonosim params --markdown`).

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace colonosim::params {

/// One declared parameter. Values are SI; `unit` is the SI unit symbol
/// ("1" for dimensionless). A closed range [minValue, maxValue] is valid.
struct ParameterSpec {
    std::string_view name;
    std::string_view unit;
    double defaultValue;
    double minValue;
    double maxValue;
    std::string_view help;
    std::string_view source;

    [[nodiscard]] constexpr bool accepts(double value) const
    {
        // NaN fails both comparisons, so non-finite values are refused.
        return value >= minValue && value <= maxValue;
    }
};

/// Thrown at a boundary (file, CLI, constructor of a model) when a value is
/// refused. The message names the parameter, the value and the allowed range.
class ParameterError : public std::invalid_argument {
public:
    explicit ParameterError(const std::string& message) : std::invalid_argument(message) {}
};

/// Formats "group.name = value unit is outside [min, max] unit (help)".
std::string describeRejection(std::string_view group, const ParameterSpec& spec, double value);

/// Throws ParameterError unless `spec` accepts `value`.
void require(std::string_view group, const ParameterSpec& spec, double value);

/// Binds a declared spec to a double member of a parameter struct.
template <class Owner>
struct Field {
    const ParameterSpec* spec;
    double Owner::*member;
};

/// Validates every declared field of `owner`; throws on the first refusal.
template <class Owner>
void validateFields(std::string_view group, std::span<const Field<Owner>> fields, const Owner& owner)
{
    for (const Field<Owner>& field : fields) {
        require(group, *field.spec, owner.*field.member);
    }
}

/// Sets the field called `name` after validating the value. Throws
/// ParameterError for an unknown name or a refused value.
template <class Owner>
void setField(std::string_view group, std::span<const Field<Owner>> fields, Owner& owner,
              std::string_view name, double value)
{
    for (const Field<Owner>& field : fields) {
        if (field.spec->name == name) {
            require(group, *field.spec, value);
            owner.*field.member = value;
            return;
        }
    }
    throw ParameterError(std::string(group) + "." + std::string(name) + " is not a declared parameter");
}

/// A markdown table row per spec: name | unit | default | range | help | source.
std::string markdownTable(std::string_view group, std::span<const ParameterSpec* const> specs);

template <class Owner>
std::vector<const ParameterSpec*> specsOf(std::span<const Field<Owner>> fields)
{
    std::vector<const ParameterSpec*> specs;
    specs.reserve(fields.size());
    for (const Field<Owner>& field : fields) {
        specs.push_back(field.spec);
    }
    return specs;
}

}  // namespace colonosim::params
