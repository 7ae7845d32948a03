#include "curricula/XmlRoot.h"

namespace colonosim::curricula {

const tinyxml2::XMLElement* parseRoot(tinyxml2::XMLDocument& document, const std::string& xml,
                                      const std::string& label, const char* rootName,
                                      std::vector<std::string>& errors)
{
    if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
        errors.push_back(label + ":" + std::to_string(document.ErrorLineNum()) + ": " + document.ErrorStr());
        return nullptr;
    }
    const tinyxml2::XMLElement* root = document.RootElement();
    if (!root || std::string(root->Name()) != rootName) {
        errors.push_back(label + ":1: the root element must be <" + rootName + ">");
        return nullptr;
    }
    return root;
}

}  // namespace colonosim::curricula
