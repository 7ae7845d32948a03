#pragma once
// Saves a widget as the person sees it into the screenshots folder of the build.
#include <QDir>
#include <QString>
#include <QWidget>

namespace colonosim::test {

inline QString screenshot(QWidget& widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(COLONOSIM_SCREENSHOTS));
    const QString path = QStringLiteral(COLONOSIM_SCREENSHOTS "/%1.png").arg(name);
    widget.grab().save(path);
    return path;
}

}  // namespace colonosim::test
