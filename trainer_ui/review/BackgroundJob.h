#pragma once
/// \file
/// Long work off the UI thread: one std::jthread runs the work, which reports
/// progress (done of total) and checks its stop token; the results come back
/// to the UI thread as queued signals. A job whose widget closes is stopped
/// and joined. Work that reads the records opens its own db::Database on the
/// same file (a QtSql connection must stay in the thread that made it).

#include <QObject>
#include <QString>

#include <functional>
#include <stop_token>
#include <thread>

namespace colonosim::app {

class BackgroundJob : public QObject {
    Q_OBJECT
public:
    /// `report(done, total)` may be called from the work; the work returns
    /// false when it stopped because a stop was requested, and throws a
    /// std::exception whose message is shown to the person.
    using Work = std::function<bool(std::stop_token, const std::function<void(int, int)>& report)>;

    explicit BackgroundJob(QObject* parent = nullptr) : QObject(parent) {}
    ~BackgroundJob() override;

    /// Starts `work` unless a job is running (then returns false).
    bool start(Work work);
    void cancel();
    [[nodiscard]] bool running() const { return m_running; }

Q_SIGNALS:
    void progressed(int done, int total);
    /// `error` empty on success; `cancelled` when the work stopped on request.
    void finished(bool cancelled, const QString& error);

private:
    std::jthread m_thread;
    bool m_running = false;
};

}  // namespace colonosim::app
