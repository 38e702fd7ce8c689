#pragma once
// Small painting helpers shared by the widgets that paint themselves.
#include <QColor>

#include <cmath>

namespace imudesk::ui {

// `over` laid on `under` at `amount` (0..1), as one opaque colour. Views that repaint on
// the refresh clock use it for faint lines: Qt's raster engine blends a translucent line
// span by span and hands tall blends to its thread pool (a wake-up and a wait each time),
// while an opaque cosmetic line is written pixel by pixel.
inline QColor mixColours(const QColor &under, const QColor &over, double amount)
{
    const auto channel = [amount](int a, int b) { return int(std::lround(a + (b - a) * amount)); };
    return QColor(channel(under.red(), over.red()), channel(under.green(), over.green()),
                  channel(under.blue(), over.blue()));
}

} // namespace imudesk::ui
