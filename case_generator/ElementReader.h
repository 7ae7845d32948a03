#pragma once
/// \file
/// Reads the fields of one XML element with tinyxml2, recording each problem
/// as `file:line: path.field ...` and returning nullopt for a field it could
/// not read. Used by CaseReader; the caller decides what a field means.

#include "case_generator/CaseNames.h"
#include "case_generator/Quantity.h"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tinyxml2 {
class XMLElement;
}

namespace colonosim::cases {

class ElementReader {
public:
    ElementReader(std::string fileName, std::vector<std::string>& errors)
        : m_file(std::move(fileName)), m_errors(errors)
    {}

    void error(const tinyxml2::XMLElement* at, const std::string& message);

    /// A required child holding other elements (no attributes, no text).
    const tinyxml2::XMLElement* section(const tinyxml2::XMLElement* parent, const char* name,
                                        const std::string& path);
    /// Reports every child element not named in `allowed`.
    void allowOnly(const tinyxml2::XMLElement* e, const std::string& path,
                   std::initializer_list<std::string_view> allowed);
    void allowAttributes(const tinyxml2::XMLElement* e, const std::string& path,
                         std::initializer_list<std::string_view> allowed);

    /// A number with its unit attribute, in range; returned in SI.
    std::optional<double> number(const tinyxml2::XMLElement* parent, const Quantity& q,
                                 const std::string& path, bool whole = false);
    /// A non-negative whole number without unit (identifiers: seed, attempt).
    std::optional<std::uint64_t> whole(const tinyxml2::XMLElement* parent, const char* name,
                                       const std::string& path);
    std::optional<std::string> text(const tinyxml2::XMLElement* parent, const char* name,
                                    const std::string& path, bool allowEmpty = false);
    std::optional<bool> flag(const tinyxml2::XMLElement* parent, const char* name, const std::string& path);

    template <class E>
    std::optional<E> name(const tinyxml2::XMLElement* parent, const char* element, const std::string& path)
    {
        const std::optional<std::string> t = text(parent, element, path);
        if (!t) {
            return std::nullopt;
        }
        const std::optional<E> value = parseName<E>(*t);
        if (!value) {
            error(leaf(parent, element),
                  path + "." + element + " = \"" + *t + "\" is not one of: " + allowedNames<E>());
        }
        return value;
    }

    template <class E>
    std::optional<E> nameAttribute(const tinyxml2::XMLElement* e, const char* attribute,
                                   const std::string& path)
    {
        const char* t = attributeText(e, attribute);
        if (t == nullptr) {
            error(e, path + ": missing attribute " + attribute);
            return std::nullopt;
        }
        const std::optional<E> value = parseName<E>(t);
        if (!value) {
            error(e, path + ": " + attribute + " = \"" + t + "\" is not one of: " + allowedNames<E>());
        }
        return value;
    }

private:
    /// The single child `name`, reporting a missing or repeated one.
    const tinyxml2::XMLElement* leaf(const tinyxml2::XMLElement* parent, const char* name);
    const tinyxml2::XMLElement* single(const tinyxml2::XMLElement* parent, const char* name,
                                       const std::string& path);
    /// The text of a leaf (no child elements), or nullopt after an error.
    std::optional<std::string> leafText(const tinyxml2::XMLElement* e, const std::string& path);
    static const char* attributeText(const tinyxml2::XMLElement* e, const char* attribute);

    std::string m_file;
    std::vector<std::string>& m_errors;
};

}  // namespace colonosim::cases
