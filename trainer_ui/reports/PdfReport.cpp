#include "trainer_ui/reports/PdfReport.h"

#include "trainer_ui/reports/ProgressReport.h"

#include <QBuffer>
#include <QDateTime>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>

#include <algorithm>
#include <cmath>
#include <optional>

namespace colonosim::reports {

namespace {

/// A line chart of `values` in `box`; `limit` draws a dashed horizontal line.
void drawChart(QPainter& p, const QRectF& box, const QString& title, const std::vector<double>& values,
               std::optional<double> limit, const QString& limitLabel)
{
    p.setPen(QPen(Qt::black, 6.0));
    p.drawRect(box);
    p.drawText(QRectF(box.left(), box.top() - 260, box.width(), 240), Qt::AlignLeft | Qt::AlignBottom, title);
    if (values.empty()) {
        p.drawText(box, Qt::AlignCenter, QStringLiteral("no scored sessions yet"));
        return;
    }
    double lo = *std::min_element(values.begin(), values.end());
    double hi = *std::max_element(values.begin(), values.end());
    if (limit) {
        lo = std::min(lo, *limit);
        hi = std::max(hi, *limit);
    }
    lo = std::min(lo, 0.0);
    if (hi - lo < 1e-9) {
        hi = lo + 1.0;
    }
    auto point = [&](size_t k, double v) {
        const double x =
            values.size() > 1 ? static_cast<double>(k) / static_cast<double>(values.size() - 1) : 0.5;
        return QPointF(box.left() + x * box.width(), box.bottom() - (v - lo) / (hi - lo) * box.height());
    };
    p.drawText(QRectF(box.left() - 700, box.top() - 100, 650, 200), Qt::AlignRight | Qt::AlignVCenter,
               QString::number(hi, 'g', 3));
    p.drawText(QRectF(box.left() - 700, box.bottom() - 100, 650, 200), Qt::AlignRight | Qt::AlignVCenter,
               QString::number(lo, 'g', 3));
    p.drawText(QRectF(box.left(), box.bottom() + 20, box.width(), 200), Qt::AlignCenter,
               QStringLiteral("session 1 to %1").arg(values.size()));
    if (limit) {
        p.setPen(QPen(QColor(200, 40, 40), 8.0, Qt::DashLine));
        p.drawLine(QPointF(box.left(), point(0, *limit).y()), QPointF(box.right(), point(0, *limit).y()));
        p.drawText(QRectF(box.right() - 2000, point(0, *limit).y() - 220, 1980, 200), Qt::AlignRight,
                   limitLabel);
    }
    QPainterPath path(point(0, values[0]));
    for (size_t k = 1; k < values.size(); ++k) {
        path.lineTo(point(k, values[k]));
    }
    p.setPen(QPen(QColor(20, 80, 180), 14.0));
    p.drawPath(path);
    p.setBrush(QColor(20, 80, 180));
    for (size_t k = 0; k < values.size(); ++k) {
        p.drawEllipse(point(k, values[k]), 30, 30);
    }
    p.setBrush(Qt::NoBrush);
    p.setPen(Qt::black);
}

}  // namespace

std::string pdfReport(const std::vector<db::SessionRow>& sessions, const nlohmann::json& progress,
                      const std::string& user, const PdfIssue& issue)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setResolution(1200);
        writer.setTitle((issue.certificate ? QStringLiteral("colonosim certification report: %1")
                                           : QStringLiteral("colonosim progress report: %1"))
                            .arg(QString::fromStdString(user)));
        writer.setCreator(QStringLiteral("colonosim"));
        QPainter p(&writer);
        const double width = writer.width();
        QFont title(QStringLiteral("DejaVu Sans"), 16, QFont::Bold);
        QFont body(QStringLiteral("DejaVu Sans"), 9);
        p.setFont(title);
        double y = 0;
        p.drawText(QRectF(0, y, width, 400), Qt::AlignLeft,
                   issue.certificate ? QStringLiteral("Simulated colonoscopy: certification report")
                                     : QStringLiteral("Simulated colonoscopy: progress report"));
        y += 450;
        p.setFont(body);
        const QString when = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
        const QStringList header = {
            QStringLiteral("Trainee: %1").arg(QString::fromStdString(user)),
            QStringLiteral("Completed sessions: %1 (aborted sessions never count)").arg(sessions.size()),
            (issue.certificate ? QStringLiteral("Issued by %1 on %2; curriculum colonoscopy-core")
                               : QStringLiteral("Drawn for %1 on %2; curriculum colonoscopy-core"))
                .arg(QString::fromStdString(issue.issuer), when),
        };
        for (const QString& line : header) {
            p.drawText(QRectF(0, y, width, 220), Qt::AlignLeft, line);
            y += 220;
        }
        y += 400;
        std::vector<double> composite;
        for (const auto& s : sessions) {
            if (const auto it = s.scores.find("composite"); it != s.scores.end()) {
                composite.push_back(it->second);
            }
        }
        const double chartLeft = 800, chartWidth = width - 900, chartHeight = 2200;
        drawChart(p, QRectF(chartLeft, y, chartWidth, chartHeight),
                  QStringLiteral("Composite score against the expert benchmark (0-100)"), composite,
                  std::nullopt, {});
        y += chartHeight + 600;
        const auto& lc = progress["learning_curve"];
        drawChart(p, QRectF(chartLeft, y, chartWidth, chartHeight),
                  QStringLiteral("CUSUM of cecal intubation failures (p0 %1, p1 %2)")
                      .arg(lc["acceptable_failure_rate"].get<double>())
                      .arg(lc["unacceptable_failure_rate"].get<double>()),
                  lc["cusum"].get<std::vector<double>>(), lc["cusum_h1"].get<double>(),
                  QStringLiteral("h1: unacceptable"));
        y += chartHeight + 600;
        drawChart(p, QRectF(chartLeft, y, chartWidth, chartHeight),
                  QStringLiteral("LC-CUSUM of cecal intubation (competence at h)"),
                  lc["lc_cusum"].get<std::vector<double>>(), lc["lc_cusum_h"].get<double>(),
                  QStringLiteral("h: competent"));
        y += chartHeight + 500;
        p.setFont(QFont(QStringLiteral("DejaVu Sans"), 10, QFont::Bold));
        p.drawText(
            QRectF(0, y, width, 240), Qt::AlignLeft,
            QStringLiteral("Certification rules: %1").arg(QString::fromStdString(ruleSetLabel(progress))));
        y += 300;
        p.setFont(body);
        for (const auto& r : progress["certification"]) {
            const bool met = r["met"].get<bool>();
            p.setPen(met ? QColor(20, 120, 40) : QColor(180, 30, 30));
            p.drawText(QRectF(0, y, 1000, 220), Qt::AlignLeft,
                       met ? QStringLiteral("met") : QStringLiteral("not met"));
            p.setPen(Qt::black);
            p.drawText(
                QRectF(1000, y, width - 1000, 220), Qt::AlignLeft,
                QString::fromStdString(
                    r["description"].get<std::string>() + " (observed " +
                    observedText(r["observed"].is_null() ? std::nan("") : r["observed"].get<double>()) +
                    ")"));
            y += 230;
        }
        y += 200;
        p.drawText(QRectF(0, y, width, 400), Qt::AlignLeft | Qt::TextWordWrap,
                   issue.certificate
                       ? QStringLiteral("Signed with Ed25519; check with: colonosim report verify FILE")
                       : QStringLiteral("Not a certificate: certification reports are issued and signed "
                                        "by an administrator (colonosim report --format pdf)."));
    }
    buffer.close();
    return bytes.toStdString();
}

}  // namespace colonosim::reports
