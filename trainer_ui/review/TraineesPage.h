#pragma once
/// \file
/// The cohorts this instructor may read, each with its trainees: completed
/// sessions, the last composite score and where the learning curve stands.
/// Double-clicking a trainee opens their curves.

#include "trainer_ui/app/AppContext.h"

#include <QWidget>

class QStandardItemModel;
class QTreeView;
class QLabel;

namespace colonosim::app {

class TraineesPage : public QWidget {
    Q_OBJECT
public:
    explicit TraineesPage(AppContext& context, QWidget* parent = nullptr);
    void refresh();

Q_SIGNALS:
    void traineeChosen(const QString& trainee);

private:
    AppContext& m_context;
    QStandardItemModel* m_model;
    QTreeView* m_tree;
    QLabel* m_summary;
};

}  // namespace colonosim::app
