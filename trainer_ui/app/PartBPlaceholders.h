#pragma once
/// \file
/// Stand-ins for the instructor's and administrator's home screens until
/// they are written (trainer_ui/review): the same class names, constructors
/// and signals, so the main window is wired to the real ones unchanged.

#include "trainer_ui/app/AppContext.h"

#include <QLabel>
#include <QVBoxLayout>
#include <QWidget>

namespace colonosim::app {

class InstructorHome : public QWidget {
    Q_OBJECT
public:
    explicit InstructorHome(AppContext& context, QWidget* parent = nullptr) : QWidget(parent)
    {
        setObjectName(QStringLiteral("instructorHome"));
        auto* layout = new QVBoxLayout(this);
        layout->addWidget(
            new QLabel(tr("<h2>Instructor: %1</h2>").arg(QString::fromStdString(context.actor.name))));
        layout->addStretch();
    }

Q_SIGNALS:
    void replayRequested(qint64 session);
};

class AdminHome : public QWidget {
    Q_OBJECT
public:
    explicit AdminHome(AppContext& context, QWidget* parent = nullptr) : QWidget(parent)
    {
        setObjectName(QStringLiteral("adminHome"));
        auto* layout = new QVBoxLayout(this);
        layout->addWidget(
            new QLabel(tr("<h2>Administrator: %1</h2>").arg(QString::fromStdString(context.actor.name))));
        layout->addStretch();
    }
};

}  // namespace colonosim::app
