#include "trainer_ui/review/CaseLibraryPage.h"

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseWriter.h"
#include "db/CaseLibrary.h"
#include "db/Cohorts.h"
#include "trainer_ui/review/BackgroundJob.h"
#include "trainer_ui/review/CasePreview.h"
#include "trainer_ui/review/ReadableTrainees.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace colonosim::app {

namespace {

QSpinBox* spin(const QString& name, int lo, int hi, int value, const QString& suffix = {})
{
    auto* box = new QSpinBox;
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

std::string caseName(const cases::Case& c)
{
    return "seed " + std::to_string(c.provenance.seed) + ": " + caseTitle(c).toStdString();
}

}  // namespace

CaseLibraryPage::CaseLibraryPage(AppContext& context, QWidget* parent)
    : QWidget(parent), m_context(context),
      m_ageMin(spin(QStringLiteral("ageMin"), cases::Statistics::builtIn().minAge(),
                    cases::Statistics::builtIn().maxAge(), cases::Statistics::builtIn().minAge(),
                    QStringLiteral(" y"))),
      m_ageMax(spin(QStringLiteral("ageMax"), cases::Statistics::builtIn().minAge(),
                    cases::Statistics::builtIn().maxAge(), cases::Statistics::builtIn().maxAge(),
                    QStringLiteral(" y"))),
      m_sex(new QComboBox), m_difficultyMin(spin(QStringLiteral("difficultyMin"), 1, 5, 1)),
      m_difficultyMax(spin(QStringLiteral("difficultyMax"), 1, 5, 5)),
      m_seed(spin(QStringLiteral("seed"), 0, 1000000000, 1)), m_preview(new QTextBrowser),
      m_save(new QPushButton(QStringLiteral("Save to the library"))), m_cases(new QListWidget),
      m_target(new QComboBox), m_assign(new QPushButton(QStringLiteral("Assign"))),
      m_count(spin(QStringLiteral("libraryCount"), 1, 1000, 20, QStringLiteral(" cases"))),
      m_generateLibrary(new QPushButton(QStringLiteral("Generate and save"))),
      m_cancel(new QPushButton(QStringLiteral("Cancel"))), m_progress(new QProgressBar), m_status(new QLabel),
      m_job(new BackgroundJob(this))
{
    m_sex->setObjectName(QStringLiteral("sex"));
    m_sex->addItem(QStringLiteral("any"), QString());
    m_sex->addItem(QStringLiteral("female"), QStringLiteral("F"));
    m_sex->addItem(QStringLiteral("male"), QStringLiteral("M"));
    m_preview->setObjectName(QStringLiteral("casePreview"));
    m_save->setObjectName(QStringLiteral("saveCaseButton"));
    m_cases->setObjectName(QStringLiteral("caseList"));
    m_target->setObjectName(QStringLiteral("assignTarget"));
    m_assign->setObjectName(QStringLiteral("assignButton"));
    m_generateLibrary->setObjectName(QStringLiteral("generateLibraryButton"));
    m_cancel->setObjectName(QStringLiteral("cancelLibraryButton"));
    m_progress->setObjectName(QStringLiteral("libraryProgress"));
    m_status->setObjectName(QStringLiteral("libraryStatus"));
    m_status->setWordWrap(true);
    m_save->setEnabled(false);
    m_cancel->setEnabled(false);
    m_progress->setValue(0);
    m_preview->setPlaceholderText(QStringLiteral("Generate a case to read its history and findings here."));

    auto* generateButton = new QPushButton(QStringLiteral("Generate"));
    generateButton->setObjectName(QStringLiteral("generateButton"));
    auto* ages = new QHBoxLayout;
    ages->addWidget(m_ageMin);
    ages->addWidget(new QLabel(QStringLiteral("to")));
    ages->addWidget(m_ageMax);
    auto* difficulty = new QHBoxLayout;
    difficulty->addWidget(m_difficultyMin);
    difficulty->addWidget(new QLabel(QStringLiteral("to")));
    difficulty->addWidget(m_difficultyMax);
    auto* constraintsBox = new QGroupBox(QStringLiteral("Generator"));
    auto* form = new QFormLayout(constraintsBox);
    form->addRow(QStringLiteral("Age:"), ages);
    form->addRow(QStringLiteral("Sex:"), m_sex);
    form->addRow(QStringLiteral("Difficulty (1-5):"), difficulty);
    form->addRow(QStringLiteral("Seed:"), m_seed);
    form->addRow(generateButton);

    auto* libraryBox = new QGroupBox(QStringLiteral("Generate a library (seeds from the seed above)"));
    auto* libraryRow = new QHBoxLayout(libraryBox);
    libraryRow->addWidget(m_count);
    libraryRow->addWidget(m_generateLibrary);
    libraryRow->addWidget(m_progress, 1);
    libraryRow->addWidget(m_cancel);

    auto* left = new QVBoxLayout;
    left->addWidget(constraintsBox);
    left->addWidget(new QLabel(QStringLiteral("Preview:")));
    left->addWidget(m_preview, 1);
    left->addWidget(m_save);

    auto* assignRow = new QHBoxLayout;
    assignRow->addWidget(new QLabel(QStringLiteral("Assign to:")));
    assignRow->addWidget(m_target, 1);
    assignRow->addWidget(m_assign);
    auto* right = new QVBoxLayout;
    right->addWidget(new QLabel(QStringLiteral("Case library:")));
    right->addWidget(m_cases, 1);
    right->addLayout(assignRow);

    auto* columns = new QHBoxLayout;
    columns->addLayout(left, 1);
    columns->addLayout(right, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(libraryBox);
    layout->addWidget(m_status);

    connect(generateButton, &QPushButton::clicked, this, &CaseLibraryPage::generate);
    connect(m_save, &QPushButton::clicked, this, &CaseLibraryPage::save);
    connect(m_assign, &QPushButton::clicked, this, &CaseLibraryPage::assign);
    connect(m_generateLibrary, &QPushButton::clicked, this, &CaseLibraryPage::generateLibrary);
    connect(m_cancel, &QPushButton::clicked, m_job, &BackgroundJob::cancel);
    connect(m_job, &BackgroundJob::progressed, this, [this](int done, int total) {
        m_progress->setMaximum(total);
        m_progress->setValue(done);
    });
    connect(m_job, &BackgroundJob::finished, this, [this](bool cancelled, const QString& error) {
        m_generateLibrary->setEnabled(true);
        m_cancel->setEnabled(false);
        refresh();
        if (!error.isEmpty()) {
            say(QStringLiteral("The library was not completed: %1").arg(error), true);
        } else if (cancelled) {
            say(QStringLiteral("Cancelled after %1 of %2 cases; the cases saved so far stay in the library.")
                    .arg(m_progress->value())
                    .arg(m_progress->maximum()));
        } else {
            say(QStringLiteral("%1 cases generated and saved.").arg(m_progress->maximum()));
        }
    });
    refresh();
}

void CaseLibraryPage::say(const QString& text, bool error)
{
    m_status->setStyleSheet(error ? QStringLiteral("color: #b01c1c") : QString());
    m_status->setText(text);
}

void CaseLibraryPage::refresh()
{
    m_cases->clear();
    db::CaseLibrary library(m_context.database);
    for (const db::CaseRow& c : library.cases(m_context.actor)) {
        auto* item =
            new QListWidgetItem(QStringLiteral("%1  %2").arg(c.id).arg(QString::fromStdString(c.name)));
        item->setData(Qt::UserRole, c.id);
        m_cases->addItem(item);
    }
    const QString target = m_target->currentText();
    m_target->clear();
    for (const db::CohortRow& c : db::readableCohorts(m_context.database, m_context.actor)) {
        m_target->addItem(QStringLiteral("cohort %1").arg(QString::fromStdString(c.name)),
                          QStringList{QStringLiteral("cohort"), QString::fromStdString(c.name)});
    }
    for (const std::string& t : readableTrainees(m_context.records, m_context.actor)) {
        m_target->addItem(QStringLiteral("trainee %1").arg(QString::fromStdString(t)),
                          QStringList{QStringLiteral("trainee"), QString::fromStdString(t)});
    }
    if (const int k = m_target->findText(target); k >= 0) {
        m_target->setCurrentIndex(k);
    }
}

cases::Constraints CaseLibraryPage::constraints() const
{
    const auto& stats = cases::Statistics::builtIn();
    cases::Constraints c;
    if (m_ageMin->value() > stats.minAge()) {
        c.ageMin = m_ageMin->value();
    }
    if (m_ageMax->value() < stats.maxAge()) {
        c.ageMax = m_ageMax->value();
    }
    if (const QString sex = m_sex->currentData().toString(); !sex.isEmpty()) {
        c.sex = sex == QStringLiteral("F") ? cases::Sex::Female : cases::Sex::Male;
    }
    if (m_difficultyMin->value() > 1) {
        c.difficultyMin = m_difficultyMin->value();
    }
    if (m_difficultyMax->value() < 5) {
        c.difficultyMax = m_difficultyMax->value();
    }
    return c;
}

void CaseLibraryPage::generate()
{
    if (m_ageMin->value() > m_ageMax->value() || m_difficultyMin->value() > m_difficultyMax->value()) {
        say(QStringLiteral("The lower bound of a range is above its upper bound (age %1 to %2 y, difficulty "
                           "%3 to %4): no case can meet it.")
                .arg(m_ageMin->value())
                .arg(m_ageMax->value())
                .arg(m_difficultyMin->value())
                .arg(m_difficultyMax->value()),
            true);
        return;
    }
    try {
        m_generated =
            cases::CaseGenerator().generate(static_cast<std::uint64_t>(m_seed->value()), constraints());
        m_preview->setHtml(casePreviewHtml(*m_generated));
        m_save->setEnabled(true);
        say(QStringLiteral("Generated: %1. Read the preview, then save it to the library.")
                .arg(caseTitle(*m_generated)));
    } catch (const std::exception& e) {
        m_generated.reset();
        m_save->setEnabled(false);
        m_preview->clear();
        say(QStringLiteral("No case was generated: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void CaseLibraryPage::save()
{
    if (!m_generated) {
        return;
    }
    try {
        const qint64 id = m_context.records.storeCase(m_context.actor, caseName(*m_generated),
                                                      cases::writeCase(*m_generated));
        refresh();
        for (int k = 0; k < m_cases->count(); ++k) {
            if (m_cases->item(k)->data(Qt::UserRole).toLongLong() == id) {
                m_cases->setCurrentRow(k);
            }
        }
        say(QStringLiteral("Saved as case %1. Choose whom to assign it to.").arg(id));
    } catch (const std::exception& e) {
        say(QStringLiteral("The case was not saved: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void CaseLibraryPage::assign()
{
    const QListWidgetItem* item = m_cases->currentItem();
    if (!item || m_target->currentIndex() < 0) {
        say(QStringLiteral("Choose a case in the library and a trainee or cohort first."), true);
        return;
    }
    const qint64 caseId = item->data(Qt::UserRole).toLongLong();
    const QStringList target = m_target->currentData().toStringList();
    try {
        db::CaseLibrary library(m_context.database);
        if (target[0] == QStringLiteral("cohort")) {
            library.assignToCohort(m_context.actor, caseId, target[1].toStdString());
        } else {
            library.assignToTrainee(m_context.actor, caseId, target[1].toStdString());
        }
        say(QStringLiteral("Case %1 is assigned to %2 %3.").arg(caseId).arg(target[0], target[1]));
    } catch (const std::exception& e) {
        say(QStringLiteral("The case was not assigned: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void CaseLibraryPage::generateLibrary()
{
    const cases::Constraints wanted = constraints();
    const auto first = static_cast<std::uint64_t>(m_seed->value());
    const int count = m_count->value();
    const std::filesystem::path file = m_context.database.path();
    const db::Actor actor = m_context.actor;
    m_progress->setRange(0, count);
    m_progress->setValue(0);
    if (!m_job->start([=](std::stop_token stop, const std::function<void(int, int)>& report) {
            db::Database database(file);
            db::Records records(database);
            const cases::CaseGenerator generator;
            for (int k = 0; k < count; ++k) {
                if (stop.stop_requested()) {
                    return false;
                }
                const cases::Case c = generator.generate(first + static_cast<std::uint64_t>(k), wanted);
                records.storeCase(actor, caseName(c), cases::writeCase(c));
                report(k + 1, count);
            }
            return true;
        })) {
        return;
    }
    m_generateLibrary->setEnabled(false);
    m_cancel->setEnabled(true);
    say(QStringLiteral("Generating %1 cases…").arg(count));
}

}  // namespace colonosim::app
