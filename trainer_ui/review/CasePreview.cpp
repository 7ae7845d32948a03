#include "trainer_ui/review/CasePreview.h"

#include "case_generator/CaseNames.h"
#include "case_generator/SceneSettings.h"

#include <QStringList>

#include <cmath>
#include <optional>
#include <string>

namespace colonosim::app {

namespace {

template <class E>
QString name(E value)
{
    const std::string_view text = cases::nameOf(value);
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()))
        .replace(QLatin1Char('_'), QLatin1Char(' '));
}

QString yesNo(bool value)
{
    return value ? QStringLiteral("yes") : QStringLiteral("no");
}

}  // namespace

QString caseTitle(const cases::Case& c)
{
    return QStringLiteral("%1 %2, %3 %4 y, %5, difficulty %6/5, %7 lesion(s)")
        .arg(QString::fromStdString(c.patient.givenName), QString::fromStdString(c.patient.familyName),
             name(c.patient.sex))
        .arg(c.patient.age)
        .arg(name(c.indication))
        .arg(c.difficulty.level)
        .arg(c.lesions.size());
}

QString casePreviewHtml(const cases::Case& c)
{
    QString html;
    html += QStringLiteral("<h3>%1 %2</h3>")
                .arg(QString::fromStdString(c.patient.givenName).toHtmlEscaped(),
                     QString::fromStdString(c.patient.familyName).toHtmlEscaped());
    html += QStringLiteral("<p>%1, %2 years, %3 m, %4 kg (BMI %5 kg/m²). Indication: %6.</p>")
                .arg(c.patient.sex == cases::Sex::Female ? QStringLiteral("Female") : QStringLiteral("Male"))
                .arg(c.patient.age)
                .arg(c.patient.height, 0, 'f', 2)
                .arg(c.patient.weight, 0, 'f', 0)
                .arg(c.patient.bmi, 0, 'f', 1)
                .arg(name(c.indication));
    html += QStringLiteral("<p><b>History:</b> prior abdominal surgery %1; hysterectomy %2; "
                           "anticoagulation: %3.</p>")
                .arg(yesNo(c.history.priorAbdominalSurgery), yesNo(c.history.hysterectomy),
                     name(c.history.anticoagulant));
    html += QStringLiteral("<p><b>Preparation:</b> Boston Bowel Preparation Scale %1 of 9 (right %2, "
                           "transverse %3, left %4).</p>")
                .arg(c.environment.bostonTotal())
                .arg(c.environment.preparation[0].boston)
                .arg(c.environment.preparation[1].boston)
                .arg(c.environment.preparation[2].boston);
    html += QStringLiteral("<p><b>Findings:</b></p><ul>");
    for (const cases::Lesion& l : c.lesions) {
        html += QStringLiteral("<li>%1 mm %2 (Paris %3) in the %4, %5 cm from its anal end</li>")
                    .arg(l.size * 1e3, 0, 'f', 0)
                    .arg(name(l.histology), name(l.paris), name(l.place.segment))
                    .arg(l.place.position * 1e2, 0, 'f', 0);
    }
    if (c.lesions.empty()) {
        html += QStringLiteral("<li>no lesion</li>");
    }
    if (!c.diverticula.empty()) {
        html += QStringLiteral("<li>%1 diverticulum/diverticula</li>").arg(c.diverticula.size());
    }
    if (c.colitis != cases::ColitisExtent::None) {
        html += QStringLiteral("<li>colitis: %1</li>").arg(name(c.colitis));
    }
    if (c.hemorrhoidGrade > 0) {
        html += QStringLiteral("<li>haemorrhoids, grade %1</li>").arg(c.hemorrhoidGrade);
    }
    if (!c.adhesions.empty()) {
        html += QStringLiteral("<li>%1 adhesion(s)</li>").arg(c.adhesions.size());
    }
    html += QStringLiteral("</ul><p><b>Colon:</b> %1 m along its centreline.</p>")
                .arg(c.anatomy.colonLength(), 0, 'f', 2);
    if (const std::optional<std::string> reason = cases::cecumOutOfReach(c)) {
        QString sentence = QString::fromStdString(*reason).toHtmlEscaped();
        sentence[0] = sentence[0].toUpper();
        html += QStringLiteral("<p style='color:#a02000'><b>Out of reach:</b> %1.</p>").arg(sentence);
    }
    html += QStringLiteral("<p><b>Difficulty:</b> %1 of 5").arg(c.difficulty.level);
    QStringList factors;
    for (const cases::DifficultyFactor& f : c.difficulty.factors) {
        factors << QStringLiteral("%1 (+%2)").arg(QString::fromStdString(f.name)).arg(f.points, 0, 'g', 2);
    }
    if (!factors.isEmpty()) {
        html += QStringLiteral(": ") + factors.join(QStringLiteral(", "));
    }
    html += QStringLiteral(".</p><p style='color:#555'>Seed %1, attempt %2%3.</p>")
                .arg(c.provenance.seed)
                .arg(c.provenance.attempt)
                .arg(c.provenance.constraints.empty() ? QString()
                                                      : QStringLiteral(", constraints ") +
                                                            QString::fromStdString(c.provenance.constraints));
    return html;
}

}  // namespace colonosim::app
