#include "common/window_helpers.h"

#include <QImageWriter>
#include <QMessageBox>
#include <QPixmap>
#include <QWidget>

namespace imudesk::ui {

void WindowHelpers::showError(QWidget *parent, QPointer<QMessageBox> &box, const QString &title,
                              const QString &message)
{
    if (box) {
        constexpr qsizetype kMaxText = 4000;
        if (box->text().size() < kMaxText)
            box->setText(box->text() + QStringLiteral("\n\n") + message);
        return;
    }
    auto *b = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, parent);
    b->setAttribute(Qt::WA_DeleteOnClose);
    b->setWindowModality(Qt::NonModal);
    b->show();
    box = b;
}

bool WindowHelpers::saveScreenshot(QWidget *window, const QString &path, QString *error)
{
    QImageWriter writer(path, "png");
    if (!writer.write(window->grab().toImage())) {
        if (error)
            *error = tr("Could not save the screenshot to %1: %2").arg(path, writer.errorString());
        return false;
    }
    return true;
}

} // namespace imudesk::ui
