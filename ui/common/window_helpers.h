#pragma once
// What every top-level window of ImuDesk does the same way: report an error without blocking,
// and save itself as a PNG.
#include <QCoreApplication>
#include <QPointer>
#include <QString>

QT_BEGIN_NAMESPACE
class QMessageBox;
class QWidget;
QT_END_NAMESPACE

namespace imudesk::ui {

class WindowHelpers {
    Q_DECLARE_TR_FUNCTIONS(imudesk::ui::WindowHelpers)

public:
    // A non-modal warning box over `parent`; while `box` is still open, the message is appended
    // to it instead of opening another (bounded, so a storm of errors cannot grow it forever).
    static void showError(QWidget *parent, QPointer<QMessageBox> &box, const QString &title, const QString &message);
    // The window as a PNG; false with a reason (translated) when it cannot be written.
    static bool saveScreenshot(QWidget *window, const QString &path, QString *error);
};

} // namespace imudesk::ui
