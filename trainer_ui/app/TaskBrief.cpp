#include "trainer_ui/app/TaskBrief.h"

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseWriter.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSpinBox>
#include <QVBoxLayout>

namespace colonosim::app {

namespace {
QString indicationWords(cases::Indication indication)
{
    switch (indication) {
    case cases::Indication::Screening: return QObject::tr("screening colonoscopy");
    case cases::Indication::PositiveStoolTest: return QObject::tr("positive faecal immunochemical test");
    case cases::Indication::Surveillance: return QObject::tr("surveillance after previous polyps");
    case cases::Indication::Symptoms:
        return QObject::tr("symptoms (change in bowel habit, bleeding or anaemia)");
    }
    return {};
}

QString medicationWords(cases::Anticoagulant drug)
{
    switch (drug) {
    case cases::Anticoagulant::None: return QObject::tr("no anticoagulant or antiplatelet drug");
    case cases::Anticoagulant::Antiplatelet: return QObject::tr("an antiplatelet drug");
    case cases::Anticoagulant::VitaminKAntagonist: return QObject::tr("a vitamin K antagonist (warfarin)");
    case cases::Anticoagulant::Doac: return QObject::tr("a direct oral anticoagulant");
    }
    return {};
}

QString bostonWords(int total)
{
    if (total >= 8) {
        return QObject::tr("excellent");
    }
    if (total >= 6) {
        return QObject::tr("adequate");
    }
    return QObject::tr("inadequate");
}
}  // namespace

TaskBrief::TaskBrief(AppContext& context, const curricula::Task& task, std::optional<std::uint64_t> seed,
                     QWidget* parent)
    : QWidget(parent), m_context(context), m_task(task)
{
    setObjectName(QStringLiteral("taskBrief"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("<h2>%1</h2>").arg(QString::fromStdString(task.title).toHtmlEscaped())));

    auto* columns = new QHBoxLayout;
    auto* patient = new QGroupBox(tr("Case history"));
    auto* patientLayout = new QVBoxLayout(patient);
    m_history = new QLabel;
    m_history->setObjectName(QStringLiteral("caseHistory"));
    m_history->setWordWrap(true);
    m_history->setTextFormat(Qt::RichText);
    m_history->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    patientLayout->addWidget(m_history);
    auto* another = new QPushButton(tr("Another patient for this task"));
    another->setObjectName(QStringLiteral("anotherCase"));
    connect(another, &QPushButton::clicked, this,
            [this] { generate(QRandomGenerator::global()->generate64()); });
    patientLayout->addWidget(another, 0, Qt::AlignLeft);
    columns->addWidget(patient, 1);

    auto* aims = new QGroupBox(tr("Instructions and learning objectives"));
    auto* aimsLayout = new QVBoxLayout(aims);
    QString objectives;
    for (const std::string& objective : task.objectives) {
        objectives += QStringLiteral("<li>%1</li>").arg(QString::fromStdString(objective).toHtmlEscaped());
    }
    auto* text = new QLabel(tr("<p>%1</p><p><b>Learning objectives</b></p><ul>%2</ul><p>Time limit: %3 min. "
                               "Benchmark: %4.</p>")
                                .arg(QString::fromStdString(task.instructions).toHtmlEscaped(), objectives)
                                .arg(task.maxTime / 60.0, 0, 'f', 0)
                                .arg(QString::fromStdString(task.benchmark)));
    text->setObjectName(QStringLiteral("taskInstructions"));
    text->setWordWrap(true);
    text->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    aimsLayout->addWidget(text);
    aimsLayout->addStretch(1);
    columns->addWidget(aims, 1);
    layout->addLayout(columns);

    auto* how = new QGroupBox(tr("How you will drive the scope"));
    auto* form = new QFormLayout(how);
    m_driver = new QComboBox;
    m_driver->setObjectName(QStringLiteral("driverChoice"));
    m_driver->addItem(tr("Keyboard and mouse"), static_cast<int>(Driver::Keyboard));
    m_driver->addItem(tr("Gamepad (the first one connected)"), static_cast<int>(Driver::Gamepad));
    m_driver->addItem(tr("Haptic device (colonosim-hdc connects to the port below)"),
                      static_cast<int>(Driver::Haptic));
    m_driver->addItem(tr("Autopilot: watch the scripted expert"), static_cast<int>(Driver::Autopilot));
    form->addRow(tr("Input"), m_driver);
    m_port = new QSpinBox;
    m_port->setObjectName(QStringLiteral("hapticPort"));
    m_port->setRange(1024, 65535);
    m_port->setValue(18944);
    form->addRow(tr("Haptic device port"), m_port);
    m_timeLimit = new QDoubleSpinBox;
    m_timeLimit->setObjectName(QStringLiteral("timeLimit"));
    m_timeLimit->setRange(1.0, task.maxTime);
    m_timeLimit->setValue(task.maxTime);
    m_timeLimit->setDecimals(0);
    m_timeLimit->setSuffix(tr(" s"));
    form->addRow(tr("End the procedure after"), m_timeLimit);
    layout->addWidget(how);
    layout->addStretch(1);
    const auto portForHaptic = [this] {
        m_port->setEnabled(static_cast<Driver>(m_driver->currentData().toInt()) == Driver::Haptic);
    };
    connect(m_driver, &QComboBox::currentIndexChanged, this, portForHaptic);
    portForHaptic();

    auto* buttons = new QHBoxLayout;
    auto* back = new QPushButton(tr("Back to the curriculum"));
    back->setObjectName(QStringLiteral("backToCurriculum"));
    connect(back, &QPushButton::clicked, this, &TaskBrief::backRequested);
    auto* start = new QPushButton(tr("Start the procedure"));
    start->setObjectName(QStringLiteral("startProcedure"));
    start->setDefault(true);
    connect(start, &QPushButton::clicked, this, [this] {
        if (m_case) {
            Q_EMIT startRequested();
        }
    });
    buttons->addWidget(back);
    buttons->addStretch();
    buttons->addWidget(start);
    layout->addLayout(buttons);

    generate(seed.value_or(QRandomGenerator::global()->generate64()));
}

void TaskBrief::generate(std::uint64_t seed)
{
    try {
        m_case = cases::CaseGenerator().generate(seed, m_task.constraints);
        m_history->setText(caseHistory(*m_case));
    } catch (const std::exception& error) {
        m_case.reset();
        m_history->setText(tr("No patient could be generated for this task: %1")
                               .arg(QString::fromStdString(error.what()).toHtmlEscaped()));
    }
}

QString TaskBrief::caseHistory(const cases::Case& c)
{
    const cases::Patient& p = c.patient;
    const cases::Environment& e = c.environment;
    QString history = tr("<p><b>%1 %2</b>, %3, %4 years, BMI %5 kg/m².</p>")
                          .arg(QString::fromStdString(p.givenName).toHtmlEscaped(),
                               QString::fromStdString(p.familyName).toHtmlEscaped(),
                               p.sex == cases::Sex::Female ? tr("woman") : tr("man"))
                          .arg(p.age)
                          .arg(p.bmi, 0, 'f', 1);
    history += tr("<p><b>Indication</b>: %1.</p>").arg(indicationWords(c.indication));
    QStringList past;
    if (c.history.priorAbdominalSurgery) {
        past << tr("previous abdominal surgery");
    }
    if (c.history.hysterectomy) {
        past << tr("hysterectomy");
    }
    history += tr("<p><b>History</b>: %1.</p>")
                   .arg(past.isEmpty() ? tr("no abdominal surgery") : past.join(tr(", ")));
    history += tr("<p><b>Medication</b>: %1.</p>").arg(medicationWords(c.history.anticoagulant));
    history +=
        tr("<p><b>Preparation</b>: Boston bowel preparation score %1 of 9 (%2; right %3, transverse %4, "
           "left %5).</p>")
            .arg(e.bostonTotal())
            .arg(bostonWords(e.bostonTotal()))
            .arg(e.preparation[0].boston)
            .arg(e.preparation[1].boston)
            .arg(e.preparation[2].boston);
    history += tr("<p><b>Difficulty</b>: %1 of 5. Case seed %2 (the same seed gives the same patient).</p>")
                   .arg(c.difficulty.level)
                   .arg(c.provenance.seed);
    return history;
}

ProcedureOptions TaskBrief::options() const
{
    ProcedureOptions out;
    out.driver = static_cast<Driver>(m_driver->currentData().toInt());
    out.hapticPort = m_port->value();
    out.timeLimit = m_timeLimit->value();
    return out;
}

std::string TaskBrief::caseXml() const
{
    return m_case ? cases::writeCase(*m_case) : std::string();
}

qint64 TaskBrief::storeCase()
{
    const std::string name = m_task.id + "-seed-" + std::to_string(m_case->provenance.seed) + ".xml";
    return m_context.records.storeCase(m_context.actor, name, caseXml());
}

}  // namespace colonosim::app
