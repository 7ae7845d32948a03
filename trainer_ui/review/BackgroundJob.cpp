#include "trainer_ui/review/BackgroundJob.h"

#include <QMetaObject>

#include <exception>

namespace colonosim::app {

BackgroundJob::~BackgroundJob()
{
    m_thread.request_stop();
    if (m_thread.joinable()) {
        m_thread.join();
    }
}

bool BackgroundJob::start(Work work)
{
    if (m_running) {
        return false;
    }
    if (m_thread.joinable()) {
        m_thread.join();
    }
    m_running = true;
    m_thread = std::jthread([this, work = std::move(work)](std::stop_token stop) {
        const auto report = [this](int done, int total) {
            QMetaObject::invokeMethod(
                this, [this, done, total] { Q_EMIT progressed(done, total); }, Qt::QueuedConnection);
        };
        bool completed = false;
        QString error;
        try {
            completed = work(stop, report);
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        const bool cancelled = !completed && error.isEmpty();
        QMetaObject::invokeMethod(
            this,
            [this, cancelled, error] {
                m_running = false;
                Q_EMIT finished(cancelled, error);
            },
            Qt::QueuedConnection);
    });
    return true;
}

void BackgroundJob::cancel()
{
    m_thread.request_stop();
}

}  // namespace colonosim::app
