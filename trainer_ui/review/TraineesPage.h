#pragma once
/// \file
/// The cohorts this instructor may read, each with its trainees: completed
/// sessions, the last composite score and where the learning curve stands.
/// Double-clicking a trainee opens their curves.

#include "trainer_ui/app/AppContext.h"

#include "trainer_ui/review/LazyPage.h"

class QStandardItemModel;
class QTreeView;
class QLabel;

namespace colonosim::app {

class TraineeSessions;

class TraineesPage : public LazyPage {
    Q_OBJECT
public:
    TraineesPage(AppContext& context, TraineeSessions& sessions, QWidget* parent = nullptr);

Q_SIGNALS:
    void traineeChosen(const QString& trainee);

protected:
    void reload() override;

private:
    AppContext& m_context;
    TraineeSessions& m_cache;
    QStandardItemModel* m_model;
    QTreeView* m_tree;
    QLabel* m_summary;
};

}  // namespace colonosim::app
