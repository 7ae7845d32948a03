// The instructor's home screen, driven as a person would: the cohort's
// trainees, a learning curve with points and the benchmark, the CUSUM charts,
// the session list with Replay, the comparison of two sessions, and the case
// library (generate with constraints, preview, save, assign to a cohort; a
// library of cases with progress and Cancel). A student who tries to assign
// is refused by the db layer.
#include "trainer_ui/review/InstructorHome.h"
#include "case_generator/CaseGenerator.h"
#include "db/CaseLibrary.h"
#include "tests/review/ReviewRecords.h"
#include "tests/review/Screenshot.h"
#include "trainer_ui/review/CasePreview.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QLabel>
#include <QLineSeries>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTableView>
#include <QTest>
#include <QTextBrowser>
#include <QTreeView>

#include <gtest/gtest.h>

namespace {

using namespace colonosim;

template <class T>
T* child(QWidget& root, const char* name)
{
    T* found = root.findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
}

void choose(QComboBox* box, const QString& text)
{
    const int k = box->findText(text, Qt::MatchStartsWith);
    ASSERT_GE(k, 0) << text.toStdString();
    box->setCurrentIndex(k);
}

struct Instructor : ::testing::Test {
    test::ReviewRecords& data = test::ReviewRecords::instance();
    app::AppContext context{*data.database, *data.records, data.teacher, data.dir};
    app::InstructorHome home{context};
    QTabWidget* tabs = nullptr;

    void SetUp() override
    {
        home.resize(1400, 900);
        home.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&home));
        tabs = child<QTabWidget>(home, "instructorTabs");
    }
    void open(int tab, const char* shot)
    {
        tabs->setCurrentIndex(tab);
        QApplication::processEvents();
        test::screenshot(home, QString::fromLatin1(shot));
    }
};

TEST_F(Instructor, SeesTheCohortWithItsTrainees)
{
    open(0, "instructor-1-trainees");
    auto* tree = child<QTreeView>(home, "traineeTree");
    const auto* model = qobject_cast<const QStandardItemModel*>(tree->model());
    ASSERT_EQ(model->rowCount(), 1) << "the teacher is assigned to cohort A only";
    const QStandardItem* cohort = model->item(0);
    EXPECT_EQ(cohort->text(), QStringLiteral("A"));
    ASSERT_EQ(cohort->rowCount(), 2);
    EXPECT_EQ(cohort->child(0, 0)->text(), QStringLiteral("ada"));
    EXPECT_EQ(cohort->child(0, 1)->text(), QString::number(data.adaSessions.size()));
    EXPECT_EQ(cohort->child(1, 0)->text(), QStringLiteral("bob"));
}

TEST_F(Instructor, SeesALearningCurveWithTheBenchmarkAndTheCusumCharts)
{
    tabs->setCurrentIndex(1);
    choose(child<QComboBox>(home, "curveTrainee"), QStringLiteral("ada"));
    choose(child<QComboBox>(home, "curveMetric"), QStringLiteral("Deepest insertion"));
    open(1, "instructor-2-learning-curves");
    QChart* metric = child<QChartView>(home, "metricChart")->chart();
    int points = -1;
    bool band = false;
    for (QAbstractSeries* s : metric->series()) {
        if (auto* dots = qobject_cast<QScatterSeries*>(s)) {
            points = static_cast<int>(dots->count());
        }
        band = band || s->type() == QAbstractSeries::SeriesTypeArea;
    }
    EXPECT_EQ(points, static_cast<int>(data.adaSessions.size()));
    EXPECT_TRUE(band) << "the benchmark's acceptable zone is drawn";

    // Double-clicking a trainee on the first page opens their curves.
    tabs->setCurrentIndex(0);
    QApplication::processEvents();
    auto* tree = child<QTreeView>(home, "traineeTree");
    const QModelIndex bob = tree->model()->index(1, 0, tree->model()->index(0, 0));
    ASSERT_FALSE(tree->visualRect(bob).isEmpty());
    // As a person's double-click arrives: a click, then the double-click.
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, tree->visualRect(bob).center());
    QTest::mouseDClick(tree->viewport(), Qt::LeftButton, {}, tree->visualRect(bob).center());
    EXPECT_EQ(tabs->currentIndex(), 1);
    EXPECT_EQ(child<QComboBox>(home, "curveTrainee")->currentText(), QStringLiteral("bob"));
    choose(child<QComboBox>(home, "curveTrainee"), QStringLiteral("ada"));
    for (const char* name : {"cusumChart", "lcCusumChart"}) {
        QChart* chart = child<QChartView>(home, name)->chart();
        int values = -1;
        int limits = 0;
        for (QAbstractSeries* s : chart->series()) {
            if (auto* dots = qobject_cast<QScatterSeries*>(s)) {
                values = static_cast<int>(dots->count());
            } else if (s->name().startsWith(QLatin1Char('h'))) {
                ++limits;
            }
        }
        EXPECT_EQ(values, static_cast<int>(data.adaSessions.size())) << name;
        EXPECT_GE(limits, 1) << name << ": the decision limits are drawn";
    }
    EXPECT_TRUE(child<QLabel>(home, "curveCaption")->text().contains(QStringLiteral("ada: 4 completed")))
        << child<QLabel>(home, "curveCaption")->text().toStdString();
}

TEST_F(Instructor, ListsTheSessionsAndAsksForAReplay)
{
    tabs->setCurrentIndex(2);
    QApplication::processEvents();
    choose(child<QComboBox>(home, "sessionTrainee"), QStringLiteral("bob"));
    auto* table = child<QTableView>(home, "sessionTable");
    ASSERT_EQ(table->model()->rowCount(), static_cast<int>(data.bobSessions.size()));
    auto* replay = child<QPushButton>(home, "replayButton");
    EXPECT_FALSE(replay->isEnabled()) << "nothing chosen yet";
    const QRect row = table->visualRect(table->model()->index(1, 0));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, row.center());
    open(2, "instructor-3-sessions");
    ASSERT_TRUE(replay->isEnabled());
    QSignalSpy spy(&home, &app::InstructorHome::replayRequested);
    QTest::mouseClick(replay, Qt::LeftButton);
    ASSERT_EQ(spy.count(), 1);
    EXPECT_EQ(spy.at(0).at(0).toLongLong(), data.bobSessions[1]);
}

TEST_F(Instructor, ComparesTwoSessions)
{
    tabs->setCurrentIndex(4);
    auto* first = child<QComboBox>(home, "compareFirst");
    auto* second = child<QComboBox>(home, "compareSecond");
    first->setCurrentIndex(first->findData(data.adaSessions[0]));
    second->setCurrentIndex(second->findData(data.adaSessions[3]));
    open(4, "instructor-5-comparison");
    auto* table = child<QTableView>(home, "comparisonTable");
    ASSERT_GT(table->model()->rowCount(), 10);
    int verdicts = 0;
    for (int r = 0; r < table->model()->rowCount(); ++r) {
        const QString better = table->model()->index(r, 4).data().toString();
        verdicts += better == QStringLiteral("A") || better == QStringLiteral("B") ? 1 : 0;
        const QString metric = table->model()->index(r, 0).data().toString();
        EXPECT_FALSE(metric.contains(u'_')) << "a label, not an identifier: " << metric.toStdString();
        if (metric == QStringLiteral("Total time")) {
            EXPECT_EQ(better, QStringLiteral("no better direction"));
        }
    }
    EXPECT_GT(verdicts, 0) << "a 1 s novice run and a 2 s expert run differ";
    EXPECT_TRUE(child<QLabel>(home, "comparisonSummary")->text().contains(QStringLiteral("A is better in")));
}

// The preview gives the colon's length and says when the scope cannot reach
// its cecum (cases::cecumOutOfReach): generated patient 7's colon is about
// 1.80 m, patient 1's 1.11 m.
TEST(CasePreview, SaysWhenTheCecumIsOutOfTheScopesReach)
{
    const cases::CaseGenerator generator;
    const QString far = app::casePreviewHtml(generator.generate(7, {}));
    EXPECT_TRUE(far.contains(QStringLiteral("<b>Colon:</b> 1.")));
    EXPECT_TRUE(far.contains(QStringLiteral("<b>Out of reach:</b> The colon is 1.")) &&
                far.contains(QStringLiteral("longer than the scope's 1.70 m working length")))
        << far.toStdString();
    const QString near = app::casePreviewHtml(generator.generate(1, {}));
    EXPECT_TRUE(near.contains(QStringLiteral("<b>Colon:</b> 1.1"))) << near.toStdString();
    EXPECT_FALSE(near.contains(QStringLiteral("Out of reach"))) << near.toStdString();
}

TEST_F(Instructor, GeneratesPreviewsSavesAndAssignsACaseToTheCohort)
{
    tabs->setCurrentIndex(3);
    child<QSpinBox>(home, "ageMin")->setValue(50);
    child<QSpinBox>(home, "ageMax")->setValue(65);
    choose(child<QComboBox>(home, "sex"), QStringLiteral("female"));
    child<QSpinBox>(home, "difficultyMax")->setValue(3);
    child<QSpinBox>(home, "seed")->setValue(7);
    QTest::mouseClick(child<QPushButton>(home, "generateButton"), Qt::LeftButton);
    const QString preview = child<QTextBrowser>(home, "casePreview")->toPlainText();
    ASSERT_TRUE(preview.contains(QStringLiteral("Female"))) << preview.toStdString();
    EXPECT_TRUE(preview.contains(QStringLiteral("History:")));
    EXPECT_TRUE(preview.contains(QStringLiteral("Findings:")));
    const QRegularExpressionMatch age = QRegularExpression(QStringLiteral("(\\d+) years")).match(preview);
    ASSERT_TRUE(age.hasMatch());
    EXPECT_GE(age.captured(1).toInt(), 50);
    EXPECT_LE(age.captured(1).toInt(), 65);

    auto* list = child<QListWidget>(home, "caseList");
    const int before = list->count();
    QTest::mouseClick(child<QPushButton>(home, "saveCaseButton"), Qt::LeftButton);
    ASSERT_EQ(list->count(), before + 1);
    ASSERT_NE(list->currentItem(), nullptr) << "the saved case is chosen";
    const qint64 saved = list->currentItem()->data(Qt::UserRole).toLongLong();
    choose(child<QComboBox>(home, "assignTarget"), QStringLiteral("cohort A"));
    QTest::mouseClick(child<QPushButton>(home, "assignButton"), Qt::LeftButton);
    open(3, "instructor-4-case-library");
    EXPECT_TRUE(
        child<QLabel>(home, "libraryStatus")->text().contains(QStringLiteral("is assigned to cohort A")))
        << child<QLabel>(home, "libraryStatus")->text().toStdString();
    db::CaseLibrary library(*data.database);
    bool reached = false;
    for (const db::AssignmentRow& a : library.assignments(data.teacher, "ada")) {
        reached = reached || (a.caseId == saved && a.cohort == "A");
    }
    EXPECT_TRUE(reached) << "ada, in cohort A, has the case";
    EXPECT_THROW(library.assignToCohort(data.ada, saved, "A"), db::AccessDenied);
}

TEST_F(Instructor, AStudentCannotAssignACase)
{
    // A case the teacher gave cohort A: ada sees it, and tries to hand it on.
    db::CaseLibrary library(*data.database);
    const qint64 caseId = data.records->storeCase(data.teacher, "for-ada.xml", "<case name=\"for-ada\"/>");
    library.assignToCohort(data.teacher, caseId, "A");
    app::AppContext student{*data.database, *data.records, data.ada, data.dir};
    app::InstructorHome screen(student);
    screen.show();
    auto* list = child<QListWidget>(screen, "caseList");
    auto* target = child<QComboBox>(screen, "assignTarget");
    ASSERT_GE(list->count(), 1);
    list->setCurrentRow(0);
    choose(target, QStringLiteral("cohort A"));
    QTest::mouseClick(child<QPushButton>(screen, "assignButton"), Qt::LeftButton);
    EXPECT_TRUE(
        child<QLabel>(screen, "libraryStatus")
            ->text()
            .contains(QStringLiteral("may not assign cases: only instructors and administrators may")))
        << child<QLabel>(screen, "libraryStatus")->text().toStdString();
}

TEST_F(Instructor, GeneratesALibraryWithProgressAndCancels)
{
    tabs->setCurrentIndex(3);
    auto* list = child<QListWidget>(home, "caseList");
    auto* status = child<QLabel>(home, "libraryStatus");
    auto* progress = child<QProgressBar>(home, "libraryProgress");
    const int before = list->count();
    child<QSpinBox>(home, "seed")->setValue(1000);
    child<QSpinBox>(home, "libraryCount")->setValue(3);
    QTest::mouseClick(child<QPushButton>(home, "generateLibraryButton"), Qt::LeftButton);
    EXPECT_TRUE(child<QPushButton>(home, "cancelLibraryButton")->isEnabled());
    EXPECT_TRUE(QTest::qWaitFor(
        [&] { return status->text().contains(QStringLiteral("generated and saved")); }, 60000))
        << status->text().toStdString();
    EXPECT_EQ(progress->value(), 3);
    EXPECT_EQ(list->count(), before + 3);

    child<QSpinBox>(home, "seed")->setValue(2000);
    child<QSpinBox>(home, "libraryCount")->setValue(1000);
    QTest::mouseClick(child<QPushButton>(home, "generateLibraryButton"), Qt::LeftButton);
    QTest::mouseClick(child<QPushButton>(home, "cancelLibraryButton"), Qt::LeftButton);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return status->text().contains(QStringLiteral("Cancelled after")); }, 60000))
        << status->text().toStdString();
    EXPECT_LT(list->count(), before + 3 + 1000);
    EXPECT_TRUE(child<QPushButton>(home, "generateLibraryButton")->isEnabled());
}

}  // namespace
