/// \file
/// `colonosim report --user NAME --format pdf|csv|xapi --out FILE [--as NAME]`
/// and `colonosim report verify FILE`.
///   pdf   the certification report (administrators): trainee, sessions, the
///         learning curves drawn with QPainter (composite score per session;
///         CUSUM and LC-CUSUM of cecal intubation) and the certification rules;
///         signed with Ed25519 and recorded in the certificates table
///         (CertificateSignature.h)
///   csv   every metric and score of every completed session, one row each
///   xapi  one xAPI statement per completed session (actor, verb "completed",
///         object the curriculum task, result with score, success, completion,
///         duration and our metrics as extensions), as a JSON array
/// verify: valid when the signature checks against the content and the
/// database holds the same record (hash, signature, public key, trainee).

#include "curricula/Curriculum.h"
#include "scoring/MetricDefinitions.h"
#include "trainer_ui/cli/CertificateSignature.h"
#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <QBuffer>
#include <QDateTime>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QUuid>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

namespace colonosim::cli {

nlohmann::json progressReport(db::Records& records, const db::Actor& actor, const std::string& user);

namespace {

/// IRI root of our activities, accounts and extensions unless --xapi-home names the organisation's own
/// (the reserved .example domain: no one else's IRIs are claimed).
constexpr const char* kXapiHome = "https://colonosim.example";

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw UsageError(path + ": cannot be read");
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    if (!out) {
        throw UsageError("--out = " + path + ": cannot be written");
    }
}

std::vector<std::string> metricColumns()
{
    std::vector<std::string> columns;
    for (const auto& d : scoring::metricDefinitions()) {
        columns.emplace_back(d.name);
    }
    return columns;
}

std::string csvReport(const std::vector<db::SessionRow>& sessions)
{
    std::set<std::string> scoreNames;
    for (const auto& s : sessions) {
        for (const auto& [name, value] : s.scores) {
            scoreNames.insert(name);
        }
    }
    const auto metrics = metricColumns();
    std::ostringstream out;
    out << std::setprecision(17) << "session,user,started_at,task,device,duration_s";
    for (const auto& m : metrics) {
        const auto* d = scoring::findMetric(m);
        out << ',' << m << " [" << d->unit << ']';
    }
    for (const auto& s : scoreNames) {
        out << ",score:" << s;
    }
    out << '\n';
    for (const auto& s : sessions) {
        out << s.id << ',' << s.user << ',' << s.startedAt << ',' << s.task << ',' << s.device << ','
            << s.duration;
        for (const auto& m : metrics) {
            out << ',';
            if (const auto it = s.metrics.find(m); it != s.metrics.end()) {
                out << it->second;
            }
        }
        for (const auto& name : scoreNames) {
            out << ',';
            if (const auto it = s.scores.find(name); it != s.scores.end()) {
                out << it->second;
            }
        }
        out << '\n';
    }
    return out.str();
}

std::string isoDuration(double seconds)
{
    std::ostringstream out;
    out << "PT" << std::fixed << std::setprecision(2) << seconds << 'S';
    return out.str();
}

nlohmann::json xapiReport(const std::vector<db::SessionRow>& sessions, const std::string& home)
{
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    nlohmann::json statements = nlohmann::json::array();
    for (const auto& s : sessions) {
        const curricula::Task* task = curriculum.value->find(s.task);
        nlohmann::json metrics;
        for (const auto& [name, value] : s.metrics) {
            metrics[name] = value;
        }
        nlohmann::json result = {{"completion", true}, {"duration", isoDuration(s.duration)}};
        if (const auto it = s.scores.find("composite"); it != s.scores.end()) {
            result["score"] = {{"scaled", it->second / 100.0}, {"raw", it->second}, {"min", 0}, {"max", 100}};
        }
        if (const auto it = s.scores.find("benchmark_met"); it != s.scores.end()) {
            result["success"] = it->second > 0.5;
        }
        result["extensions"] = {{home + "/xapi/extensions/metrics", metrics},
                                {home + "/xapi/extensions/scores", s.scores}};
        statements.push_back({
            {"id", QUuid::createUuid().toString(QUuid::WithoutBraces).toStdString()},
            {"actor",
             {{"objectType", "Agent"},
              {"name", s.user},
              {"account", {{"homePage", home}, {"name", s.user}}}}},
            {"verb",
             {{"id", "http://adlnet.gov/expapi/verbs/completed"}, {"display", {{"en-US", "completed"}}}}},
            {"object",
             {{"objectType", "Activity"},
              {"id", home + "/xapi/activities/colonoscopy-core/" + s.task},
              {"definition",
               {{"name", {{"en-US", task ? task->title : s.task}}},
                {"type", "http://adlnet.gov/expapi/activities/simulation"}}}}},
            {"result", result},
            {"context",
             {{"platform", "colonosim"},
              {"extensions",
               {{home + "/xapi/extensions/session", s.id}, {home + "/xapi/extensions/device", s.device}}}}},
            {"timestamp", s.startedAt},
        });
    }
    return statements;
}

/// A line chart of `values` in `box`; `limit` draws a dashed horizontal line.
void drawChart(QPainter& p, const QRectF& box, const QString& title, const std::vector<double>& values,
               std::optional<double> limit, const QString& limitLabel)
{
    p.setPen(QPen(Qt::black, 6.0));
    p.drawRect(box);
    p.drawText(QRectF(box.left(), box.top() - 260, box.width(), 240), Qt::AlignLeft | Qt::AlignBottom, title);
    if (values.empty()) {
        p.drawText(box, Qt::AlignCenter, QStringLiteral("no sessions yet"));
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

std::string pdfReport(const std::vector<db::SessionRow>& sessions, const nlohmann::json& progress,
                      const std::string& user, const std::string& issuer)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setResolution(1200);
        writer.setTitle(
            QStringLiteral("colonosim certification report: %1").arg(QString::fromStdString(user)));
        writer.setCreator(QStringLiteral("colonosim"));
        QPainter p(&writer);
        const double width = writer.width();
        QFont title(QStringLiteral("DejaVu Sans"), 16, QFont::Bold);
        QFont body(QStringLiteral("DejaVu Sans"), 9);
        p.setFont(title);
        double y = 0;
        p.drawText(QRectF(0, y, width, 400), Qt::AlignLeft,
                   QStringLiteral("Simulated colonoscopy: certification report"));
        y += 450;
        p.setFont(body);
        const QString when = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
        const QStringList header = {
            QStringLiteral("Trainee: %1").arg(QString::fromStdString(user)),
            QStringLiteral("Completed sessions: %1 (aborted sessions never count)").arg(sessions.size()),
            QStringLiteral("Issued by %1 on %2; curriculum colonoscopy-core")
                .arg(QString::fromStdString(issuer), when),
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
        p.drawText(QRectF(0, y, width, 240), Qt::AlignLeft, QStringLiteral("Certification rules"));
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
                   QStringLiteral("Signed with Ed25519; check with: colonosim report verify FILE"));
    }
    buffer.close();
    return bytes.toStdString();
}

int verify(const CommandLine& line, const std::string& file)
{
    const std::string bytes = readFile(file);
    const auto trailer = splitTrailer(bytes);
    if (!trailer) {
        std::cout << "invalid: " << file << " carries no colonosim signature\n";
        return 1;
    }
    const std::string sha = sha256Hex(trailer->content);
    if (!verifySignature(trailer->publicKey, trailer->signature, signedMessage(trailer->user, sha))) {
        std::cout << "invalid: the signature does not match the content (the file was changed)\n";
        return 1;
    }
    OpenRecords open = openRecords(line, std::cerr);
    const auto record = open.records->certificateBySha(sha);
    if (!record || record->signature != trailer->signature || record->publicKey != trailer->publicKey ||
        record->user != trailer->user) {
        std::cout << "invalid: the records hold no matching certificate for this file\n";
        return 1;
    }
    std::cout << "valid: certification report of " << record->user << ", issued by " << record->issuedBy
              << " on " << record->issuedAt << " (certificate " << record->id << ")\n";
    return 0;
}

}  // namespace

int runReport(std::span<char* const> args)
{
    std::vector<std::string> options = {"--user", "--format", "--out", "--xapi-home"};
    options.insert(options.end(), kRecordsOptions.begin(), kRecordsOptions.end());
    const CommandLine line(args, {"--help"}, options);
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim report --user NAME --format pdf|csv|xapi --out FILE [--as NAME] [--db "
               "FILE]\n"
               "       colonosim report verify FILE [--db FILE]\n"
               "pdf: the signed certification report (administrators); csv: every metric of every\n"
               "session; xapi: xAPI statements (JSON; --xapi-home IRI: the organisation's IRI root for\n"
               "accounts, activities and extensions). verify exits 0 when valid, 1 when invalid.\n";
        return 0;
    }
    ensureQtApplication(true);
    if (!line.positional().empty()) {
        if (line.positional()[0] != "verify" || line.positional().size() != 2) {
            throw UsageError("expected: report verify FILE (got \"" + line.positional()[0] + "\")");
        }
        return verify(line, line.positional()[1]);
    }
    const auto user = line.value("--user");
    const auto format = line.value("--format");
    const auto out = line.value("--out");
    if (!user || !format || !out) {
        throw UsageError("--user, --format and --out are required (see --help)");
    }
    if (*format != "pdf" && *format != "csv" && *format != "xapi") {
        throw UsageError("--format = " + *format + " is not one of pdf, csv, xapi");
    }
    OpenRecords open = openRecords(line, std::cerr);
    const db::Actor actor = authenticate(*open.records, line, line.value("--as").value_or(*user));
    try {
        const std::vector<db::SessionRow> sessions = open.records->sessions(actor, *user);
        if (*format == "csv") {
            writeFile(*out, csvReport(sessions));
        } else if (*format == "xapi") {
            const std::string home = line.value("--xapi-home").value_or(kXapiHome);
            if (home.rfind("https://", 0) != 0 && home.rfind("http://", 0) != 0) {
                throw UsageError("--xapi-home = " + home + " is not an http(s) IRI");
            }
            writeFile(*out, xapiReport(sessions, home).dump(2) + "\n");
        } else {
            if (actor.role != db::Role::Administrator) {
                throw db::AccessDenied(actor.name + " (" + db::roleName(actor.role) +
                                       ") may not issue certification reports: only administrators may");
            }
            const nlohmann::json progress = progressReport(*open.records, actor, *user);
            const std::string pdf = pdfReport(sessions, progress, *user, actor.name);
            const SigningKey key = signingKey(open.database->path().string() + ".signing-key");
            const std::string sha = sha256Hex(pdf);
            const std::string signature = sign(key, signedMessage(*user, sha));
            open.records->issueCertificate(actor, *user, sha, signature, key.publicKeyHex);
            writeFile(*out, pdf + trailerLine(*user, key.publicKeyHex, signature));
        }
    } catch (const db::AccessDenied& error) {
        throw UsageError(std::string("refused: ") + error.what());
    }
    std::cout << "written: " << *out << '\n';
    return 0;
}

}  // namespace colonosim::cli
