// A child process for the crash test: writes sessions to a real database file
// until it is killed. Prints "completed N" after each completed session.
// With --hang it stops after three sessions in the middle of finalising a
// fourth (its write transaction open, events half written) and waits to be killed.
#include "db/Database.h"
#include "db/RecordingCodec.h"
#include "db/Records.h"

#include <QCoreApplication>
#include <QSqlQuery>

#include <chrono>
#include <cstring>
#include <iostream>
#include <thread>

int main(int argc, char** argv)
{
    using namespace colonosim;
    QCoreApplication app(argc, argv);
    if (argc < 2) {
        std::cerr << "usage: db_session_writer DB [--hang]\n";
        return 2;
    }
    const bool hang = argc > 2 && std::strcmp(argv[2], "--hang") == 0;
    db::Database database(argv[1]);
    db::Records records(database);
    const db::Actor ada = records.authenticate("ada", "ada-password");
    procedure::Recording recording;
    for (int k = 0; k < 2000; ++k) {
        procedure::RecordedSample s{};
        s.tip = Eigen::Vector3d::Zero();
        s.time = 0.01 * k;
        s.insertion = 0.001 * k;
        s.handleForce = 3.0 + (k % 7);
        recording.samples.push_back(s);
    }
    const std::vector<char> blob = db::encodeRecording(recording);
    db::SessionResult result;
    result.recording = QByteArray(blob.data(), static_cast<qsizetype>(blob.size()));
    result.duration = 20.0;
    for (int e = 0; e < 50; ++e) {
        result.events.push_back({0.1 * e, "LoopFormed", "N"});
    }
    result.metrics = {{"total_time", 20.0}, {"cecal_intubation", 1.0}};
    result.scores = {{"composite", 50.0}};
    for (int n = 1;; ++n) {
        const qint64 session = records.beginSession(ada, std::nullopt, "navigation", "scripted");
        if (hang && n == 4) {
            QSqlQuery query(database.connection());
            query.exec(QStringLiteral("BEGIN IMMEDIATE"));
            query.exec(QStringLiteral("UPDATE sessions SET status = 'completed' WHERE id = %1").arg(session));
            for (int e = 0; e < 20; ++e) {
                query.exec(QStringLiteral(
                               "INSERT INTO events (session_id, seq, time_s, kind) VALUES (%1, %2, 0, 'x')")
                               .arg(session)
                               .arg(e));
            }
            std::cout << "mid-transaction " << session << std::endl;
            for (;;) {
                std::this_thread::sleep_for(std::chrono::seconds(1));
            }
        }
        records.completeSession(ada, session, result);
        std::cout << "completed " << n << std::endl;
    }
}
