#pragma once
/// \file
/// The start both curricula files share: parse the XML and find the root
/// element by name, with `label:line: message` errors.

#include <tinyxml2.h>

#include <string>
#include <vector>

namespace colonosim::curricula {

/// Parses `xml` into `document` and returns its root element when it is
/// named `rootName`; otherwise appends the error to `errors` and returns null.
const tinyxml2::XMLElement* parseRoot(tinyxml2::XMLDocument& document, const std::string& xml,
                                      const std::string& label, const char* rootName,
                                      std::vector<std::string>& errors);

}  // namespace colonosim::curricula
