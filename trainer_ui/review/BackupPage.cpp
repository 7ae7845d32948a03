#include "trainer_ui/review/BackupPage.h"

#include <QDateTime>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <filesystem>

namespace colonosim::app {

BackupPage::BackupPage(AppContext& context, QWidget* parent)
    : QWidget(parent), m_context(context), m_path(new QLineEdit), m_status(new QLabel)
{
    m_path->setObjectName(QStringLiteral("backupPath"));
    m_status->setObjectName(QStringLiteral("backupStatus"));
    m_status->setWordWrap(true);
    const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm"));
    m_path->setText(QString::fromStdString(
        (m_context.exportDir / ("records-backup-" + stamp.toStdString() + ".sqlite")).string()));
    auto* browse = new QPushButton(QStringLiteral("Browse…"));
    auto* run = new QPushButton(QStringLiteral("Back up now"));
    run->setObjectName(QStringLiteral("backupButton"));
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(QStringLiteral("Backup file:")));
    row->addWidget(m_path, 1);
    row->addWidget(browse);
    row->addWidget(run);
    auto* intro = new QLabel(
        QStringLiteral(
            "Copies the whole records database (%1) while the trainer keeps running. Keep the copy "
            "somewhere safe: it holds every user's records and password hashes.")
            .arg(QString::fromStdString(m_context.database.path().string())));
    intro->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(row);
    layout->addWidget(m_status);
    layout->addStretch(1);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getSaveFileName(this, QStringLiteral("Backup file"), m_path->text(),
                                                          QStringLiteral("SQLite databases (*.sqlite)"));
        if (!file.isEmpty()) {
            m_path->setText(file);
        }
    });
    connect(run, &QPushButton::clicked, this, &BackupPage::backup);
}

void BackupPage::backup()
{
    const std::filesystem::path path = m_path->text().trimmed().toStdString();
    if (path.empty()) {
        m_status->setText(QStringLiteral("Name the backup file first."));
        return;
    }
    if (std::filesystem::exists(path)) {
        m_status->setStyleSheet(QStringLiteral("color: #b01c1c"));
        m_status->setText(QStringLiteral("%1 exists already: choose another name, nothing was replaced.")
                              .arg(QString::fromStdString(path.string())));
        return;
    }
    try {
        m_context.records.backup(m_context.actor, path);
        m_status->setStyleSheet(QString());
        m_status->setText(QStringLiteral("Backed up to %1 (%2 kB).")
                              .arg(QString::fromStdString(path.string()))
                              .arg(std::filesystem::file_size(path) / 1024));
    } catch (const std::exception& e) {
        m_status->setStyleSheet(QStringLiteral("color: #b01c1c"));
        m_status->setText(QStringLiteral("No backup was taken: %1").arg(QString::fromStdString(e.what())));
    }
}

}  // namespace colonosim::app
