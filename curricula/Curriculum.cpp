#include "curricula/Curriculum.h"

#include "curricula/XmlRoot.h"

#include <tinyxml2.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace colonosim::curricula {

namespace {

class Reader {
public:
    explicit Reader(std::string label) : m_label(std::move(label)) {}

    void error(const tinyxml2::XMLElement* at, const std::string& message)
    {
        m_errors.push_back(m_label + ":" + std::to_string(at ? at->GetLineNum() : 0) + ": " + message);
    }

    std::string text(const tinyxml2::XMLElement* e, const char* attribute, bool required)
    {
        const char* value = e->Attribute(attribute);
        if (!value && required) {
            std::string message = "<";
            message += e->Name();
            message += "> needs the attribute ";
            message += attribute;
            error(e, message);
        }
        return value ? value : "";
    }

    std::optional<double> number(const tinyxml2::XMLElement* e, const char* attribute, double min, double max)
    {
        const char* value = e->Attribute(attribute);
        if (!value) {
            return std::nullopt;
        }
        double v = 0.0;
        if (e->QueryDoubleAttribute(attribute, &v) != tinyxml2::XML_SUCCESS || !(v >= min && v <= max)) {
            std::ostringstream range;
            range << min << "-" << max;
            error(e, std::string(attribute) + " = \"" + value + "\" is out of range " + range.str());
            return std::nullopt;
        }
        return v;
    }

    std::optional<int> integer(const tinyxml2::XMLElement* e, const char* attribute, int min, int max)
    {
        const auto v = number(e, attribute, min, max);
        if (v && std::floor(*v) != *v) {
            error(e,
                  std::string(attribute) + " = \"" + e->Attribute(attribute) + "\" must be a whole number");
            return std::nullopt;
        }
        return v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
    }

    std::vector<std::string> m_errors;

private:
    std::string m_label;
};

void readConstraints(Reader& r, const tinyxml2::XMLElement* e, cases::Constraints& c)
{
    static const std::set<std::string> known = {"sex",     "age_min",        "age_max",        "bmi_min",
                                                "bmi_max", "difficulty_min", "difficulty_max", "require"};
    for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
        if (!known.contains(a->Name())) {
            r.error(e, std::string("unknown constraint \"") + a->Name() +
                           "\" (allowed: sex, age_min, age_max, bmi_min, bmi_max, difficulty_min, "
                           "difficulty_max, require)");
        }
    }
    if (const char* sex = e->Attribute("sex")) {
        const std::string s = sex;
        if (s == "F") {
            c.sex = cases::Sex::Female;
        } else if (s == "M") {
            c.sex = cases::Sex::Male;
        } else {
            r.error(e, "sex = \"" + s + "\" is not one of F, M");
        }
    }
    c.ageMin = r.integer(e, "age_min", 18, 100);
    c.ageMax = r.integer(e, "age_max", 18, 100);
    c.bmiMin = r.number(e, "bmi_min", 10.0, 70.0);
    c.bmiMax = r.number(e, "bmi_max", 10.0, 70.0);
    c.difficultyMin = r.integer(e, "difficulty_min", 1, 5);
    c.difficultyMax = r.integer(e, "difficulty_max", 1, 5);
    if (c.difficultyMin && c.difficultyMax && *c.difficultyMin > *c.difficultyMax) {
        r.error(e, "difficulty_min = " + std::to_string(*c.difficultyMin) +
                       " exceeds difficulty_max = " + std::to_string(*c.difficultyMax));
    }
    if (const char* require = e->Attribute("require")) {
        try {
            c.require = cases::RequireExpression::parse(require);
        } catch (const std::exception& error) {
            r.error(e, std::string("require = \"") + require + "\": " + error.what());
        }
    }
}

std::string childText(const tinyxml2::XMLElement* e)
{
    return e && e->GetText() ? e->GetText() : "";
}

}  // namespace

const Task* Curriculum::find(const std::string& id) const
{
    for (const Task& t : tasks) {
        if (t.id == id) {
            return &t;
        }
    }
    return nullptr;
}

CurriculumRead parseCurriculum(const std::string& xml, const std::string& label)
{
    CurriculumRead result;
    Reader r(label);
    tinyxml2::XMLDocument document;
    const tinyxml2::XMLElement* root = parseRoot(document, xml, label, "curriculum", result.errors);
    if (root == nullptr) {
        return result;
    }
    Curriculum c;
    c.name = r.text(root, "name", true);
    c.version = r.integer(root, "version", 1, 1000000).value_or(1);
    if (!root->Attribute("version")) {
        r.error(root, "<curriculum> needs the attribute version");
    }
    std::set<std::string> ids;
    for (const auto* m = root->FirstChildElement("module"); m; m = m->NextSiblingElement("module")) {
        Module module{r.text(m, "id", true), r.text(m, "title", true)};
        bool anyTask = false;
        for (const auto* t = m->FirstChildElement("task"); t; t = t->NextSiblingElement("task")) {
            anyTask = true;
            Task task;
            task.module = module.id;
            task.id = r.text(t, "id", true);
            task.title = r.text(t, "title", true);
            task.benchmark = r.text(t, "benchmark", true);
            task.maxTime = r.number(t, "max_time_s", 1.0, 3600.0).value_or(900.0);
            if (const char* available = t->Attribute("available")) {
                const std::string a = available;
                if (a != "true" && a != "false") {
                    r.error(t, "available = \"" + a + "\" is not one of true, false");
                }
                task.available = a != "false";
            }
            task.unavailableReason = r.text(t, "unavailable_reason", false);
            if (const char* shape = t->Attribute("shape_view")) {
                const std::string a = shape;
                if (a != "true" && a != "false") {
                    r.error(t, "shape_view = \"" + a + "\" is not one of true, false");
                }
                task.shapeView = a != "false";
            }
            if (!task.available && task.unavailableReason.empty()) {
                r.error(t, "task \"" + task.id + "\" is unavailable: it must say why (unavailable_reason)");
            }
            if (!ids.insert(task.id).second) {
                r.error(t, "task id \"" + task.id + "\" is used twice");
            }
            task.instructions = childText(t->FirstChildElement("instructions"));
            if (task.instructions.empty()) {
                r.error(t, "task \"" + task.id + "\" needs <instructions>");
            }
            for (const auto* o = t->FirstChildElement("objective"); o;
                 o = o->NextSiblingElement("objective")) {
                task.objectives.push_back(childText(o));
            }
            if (task.objectives.empty()) {
                r.error(t, "task \"" + task.id + "\" needs at least one <objective>");
            }
            if (const auto* k = t->FirstChildElement("constraints")) {
                readConstraints(r, k, task.constraints);
            } else {
                r.error(t, "task \"" + task.id + "\" needs <constraints> for the case generator");
            }
            for (const auto* p = t->FirstChildElement("prerequisite"); p;
                 p = p->NextSiblingElement("prerequisite")) {
                const std::string prerequisite = r.text(p, "task", true);
                if (!ids.contains(prerequisite)) {
                    r.error(p, "prerequisite \"" + prerequisite +
                                   "\" is not a task defined earlier (tasks go easy to hard)");
                }
                task.prerequisites.push_back(prerequisite);
            }
            c.tasks.push_back(std::move(task));
        }
        if (!anyTask) {
            r.error(m, "module \"" + module.id + "\" has no task");
        }
        c.modules.push_back(std::move(module));
    }
    if (c.modules.empty()) {
        r.error(root, "the curriculum has no module");
    }
    result.errors = std::move(r.m_errors);
    if (result.errors.empty()) {
        result.value = std::move(c);
    }
    return result;
}

CurriculumRead readCurriculumFile(const std::filesystem::path& path)
{
    std::ifstream in(path);
    if (!in) {
        return {std::nullopt, {path.string() + ":0: cannot be read"}};
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    return parseCurriculum(buffer.str(), path.string());
}

}  // namespace colonosim::curricula
