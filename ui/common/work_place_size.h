#pragma once
// The size of a wizard or dialog that is a work place (calibration, firmware update): most of
// the screen it opens on, so that its live views are large and no text is cut, but never
// larger than that screen (a 1366x768 laptop).
class QWidget;
class QSize;

namespace imudesk::ui {

// Resizes `window` to `wanted`, bounded by 94 % of the available area of the screen of
// `anchor` (or of the window, or the primary screen), and centres it there.
void fitWorkPlace(QWidget *window, const QSize &wanted, const QWidget *anchor = nullptr);

} // namespace imudesk::ui
