#include "common/work_place_size.h"

#include <QGuiApplication>
#include <QScreen>
#include <QWidget>

namespace imudesk::ui {

void fitWorkPlace(QWidget *window, const QSize &wanted, const QWidget *anchor)
{
    const QScreen *screen = anchor ? anchor->screen() : window->screen();
    if (!screen)
        screen = QGuiApplication::primaryScreen();
    if (!screen) {
        window->resize(wanted);
        return;
    }
    const QRect avail = screen->availableGeometry();
    const QSize size = wanted.boundedTo(QSize(avail.width() * 94 / 100, avail.height() * 94 / 100));
    window->resize(size);
    window->move(avail.center() - QPoint(size.width() / 2, size.height() / 2));
}

} // namespace imudesk::ui
