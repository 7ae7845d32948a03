#pragma once
/// \file
/// A page that reads the records only when a person looks at it: refresh()
/// marks it stale, and a stale page reloads when it is shown (or at once
/// when it is visible). A home screen with many pages then opens as fast as
/// its first page.

#include <QWidget>

namespace colonosim::app {

class LazyPage : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;

    /// Reloads now when visible, else when next shown.
    void refresh()
    {
        m_stale = true;
        if (isVisible()) {
            reloadNow();
        }
    }

protected:
    virtual void reload() = 0;
    void showEvent(QShowEvent* event) override
    {
        if (m_stale) {
            reloadNow();
        }
        QWidget::showEvent(event);
    }

private:
    void reloadNow()
    {
        m_stale = false;
        reload();
    }

    bool m_stale = true;
};

}  // namespace colonosim::app
