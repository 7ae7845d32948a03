#pragma once
/// \file
/// The names the case file and the constraint grammar use for each
/// enumeration, in enumerator order. One table per enumeration drives writing,
/// reading, the error messages ("one of: ...") and the XSD's enumerations.

#include "case_generator/Case.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace colonosim::cases {

template <class E>
struct EnumNames;

template <>
struct EnumNames<Sex> {
    static constexpr std::array<std::string_view, 2> list{"F", "M"};
};
template <>
struct EnumNames<Segment> {
    static constexpr std::array<std::string_view, 8> list{"rectum",          "sigmoid",    "descending",
                                                          "splenic_flexure", "transverse", "hepatic_flexure",
                                                          "ascending",       "cecum"};
};
template <>
struct EnumNames<Indication> {
    static constexpr std::array<std::string_view, 4> list{"screening", "positive_stool_test", "surveillance",
                                                          "symptoms"};
};
template <>
struct EnumNames<Anticoagulant> {
    static constexpr std::array<std::string_view, 4> list{"none", "antiplatelet", "vitamin_k_antagonist",
                                                          "doac"};
};
template <>
struct EnumNames<Histology> {
    static constexpr std::array<std::string_view, 9> list{
        "tubular",          "tubular_high_grade",   "tubulovillous",  "villous", "hyperplastic",
        "sessile_serrated", "traditional_serrated", "adenocarcinoma", "lipoma"};
};
template <>
struct EnumNames<Paris> {
    static constexpr std::array<std::string_view, 10> list{"0-Ip",  "0-Isp", "0-Is",   "0-IIa", "0-IIb",
                                                           "0-IIc", "LST-G", "LST-NG", "1",     "2"};
};
template <>
struct EnumNames<Colour> {
    static constexpr std::array<std::string_view, 4> list{"pale", "isochromatic", "reddish", "yellowish"};
};
template <>
struct EnumNames<Surface> {
    static constexpr std::array<std::string_view, 4> list{"smooth", "granular", "lobulated", "ulcerated"};
};
template <>
struct EnumNames<ColitisExtent> {
    static constexpr std::array<std::string_view, 4> list{"none", "proctitis", "left_sided", "extensive"};
};
template <>
struct EnumNames<BowelRegion> {
    static constexpr std::array<std::string_view, 3> list{"right", "transverse", "left"};
};
template <>
struct EnumNames<TrainingTask> {
    static constexpr std::array<std::string_view, 3> list{"intubation", "detection", "polypectomy"};
};

template <class E>
[[nodiscard]] constexpr std::string_view nameOf(E value)
{
    return EnumNames<E>::list[static_cast<std::size_t>(value)];
}

template <class E>
[[nodiscard]] std::optional<E> parseName(std::string_view text)
{
    for (std::size_t i = 0; i < EnumNames<E>::list.size(); ++i) {
        if (EnumNames<E>::list[i] == text) {
            return static_cast<E>(i);
        }
    }
    return std::nullopt;
}

/// "a, b, c": the allowed names, for messages.
template <class E>
[[nodiscard]] std::string allowedNames()
{
    std::string out;
    for (const std::string_view name : EnumNames<E>::list) {
        out += out.empty() ? "" : ", ";
        out += name;
    }
    return out;
}

}  // namespace colonosim::cases
