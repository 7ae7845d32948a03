#include "case_generator/ElementReader.h"

#include <tinyxml2.h>

#include <charconv>
#include <cmath>

namespace colonosim::cases {

using tinyxml2::XMLElement;

void ElementReader::error(const XMLElement* at, const std::string& message)
{
    const int line = at != nullptr ? at->GetLineNum() : 0;
    m_errors.push_back(m_file + ":" + std::to_string(line) + ": " + message);
}

const char* ElementReader::attributeText(const XMLElement* e, const char* attribute)
{
    return e->Attribute(attribute);
}

const XMLElement* ElementReader::leaf(const XMLElement* parent, const char* name)
{
    const XMLElement* e = parent->FirstChildElement(name);
    return e != nullptr ? e : parent;
}

const XMLElement* ElementReader::single(const XMLElement* parent, const char* name, const std::string& path)
{
    const XMLElement* e = parent->FirstChildElement(name);
    if (e == nullptr) {
        error(parent, path + ": missing <" + name + ">");
        return nullptr;
    }
    if (const XMLElement* again = e->NextSiblingElement(name)) {
        error(again, path + ": <" + name + "> appears twice");
    }
    return e;
}

const XMLElement* ElementReader::section(const XMLElement* parent, const char* name, const std::string& path)
{
    const XMLElement* e = single(parent, name, path);
    if (e != nullptr) {
        allowAttributes(e, path == "case" ? name : path + "." + name, {});
    }
    return e;
}

void ElementReader::allowOnly(const XMLElement* e, const std::string& path,
                              std::initializer_list<std::string_view> allowed)
{
    for (const XMLElement* child = e->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
        bool known = false;
        for (const std::string_view name : allowed) {
            known = known || name == child->Name();
        }
        if (!known) {
            error(child, path + ": unknown element <" + child->Name() + ">");
        }
    }
}

void ElementReader::allowAttributes(const XMLElement* e, const std::string& path,
                                    std::initializer_list<std::string_view> allowed)
{
    for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a != nullptr; a = a->Next()) {
        bool known = false;
        for (const std::string_view name : allowed) {
            known = known || name == a->Name();
        }
        if (!known) {
            error(e, path + ": unknown attribute " + a->Name());
        }
    }
}

std::optional<std::string> ElementReader::leafText(const XMLElement* e, const std::string& path)
{
    if (const XMLElement* inner = e->FirstChildElement()) {
        error(inner, path + ": unknown element <" + inner->Name() + "> inside a value");
        return std::nullopt;
    }
    const char* t = e->GetText();
    return std::string(t != nullptr ? t : "");
}

std::optional<double> ElementReader::number(const XMLElement* parent, const Quantity& q,
                                            const std::string& path, bool whole)
{
    const std::string element(q.element);
    const std::string field = path + "." + element;
    const XMLElement* e = single(parent, element.c_str(), path);
    if (e == nullptr) {
        return std::nullopt;
    }
    allowAttributes(e, field, {"unit"});
    const char* unit = e->Attribute("unit");
    const std::string expected(q.unit);
    if (unit == nullptr) {
        error(e, field + ": missing unit attribute (expected unit=\"" + expected + "\")");
        return std::nullopt;
    }
    if (expected != unit) {
        error(e, field + ": unit = \"" + unit + "\", expected \"" + expected + "\"");
        return std::nullopt;
    }
    const std::optional<std::string> t = leafText(e, field);
    if (!t) {
        return std::nullopt;
    }
    const std::optional<double> value = parseNumber(*t);
    if (!value) {
        error(e, field + " = \"" + *t + "\" is not a finite decimal number");
        return std::nullopt;
    }
    if (!q.accepts(*value) || (whole && *value != std::floor(*value))) {
        error(e, field + " = " + *t + " " + expected + " is outside [" + formatFixed(q.min, q.decimals) +
                     ", " + formatFixed(q.max, q.decimals) + "] " + expected +
                     (whole ? ", whole numbers only" : "") + " (" + std::string(q.help) + ")");
        return std::nullopt;
    }
    return *value * q.siPerUnit;
}

std::optional<std::uint64_t> ElementReader::whole(const XMLElement* parent, const char* name,
                                                  const std::string& path)
{
    const std::optional<std::string> t = text(parent, name, path);
    if (!t) {
        return std::nullopt;
    }
    std::uint64_t value = 0;
    const auto result = std::from_chars(t->data(), t->data() + t->size(), value);
    if (t->empty() || result.ec != std::errc() || result.ptr != t->data() + t->size()) {
        error(leaf(parent, name), path + "." + name + " = \"" + *t + "\" is not a whole number in [0, 2^64)");
        return std::nullopt;
    }
    return value;
}

std::optional<std::string> ElementReader::text(const XMLElement* parent, const char* name,
                                               const std::string& path, bool allowEmpty)
{
    const XMLElement* e = single(parent, name, path);
    if (e == nullptr) {
        return std::nullopt;
    }
    const std::string field = path + "." + name;
    allowAttributes(e, field, {});
    std::optional<std::string> t = leafText(e, field);
    if (t && t->empty() && !allowEmpty) {
        error(e, field + " is empty");
        return std::nullopt;
    }
    return t;
}

std::optional<bool> ElementReader::flag(const XMLElement* parent, const char* name, const std::string& path)
{
    const std::optional<std::string> t = text(parent, name, path);
    if (!t) {
        return std::nullopt;
    }
    if (*t == "true" || *t == "false") {
        return *t == "true";
    }
    error(leaf(parent, name), path + "." + name + " = \"" + *t + "\" is not one of: true, false");
    return std::nullopt;
}

}  // namespace colonosim::cases
