#include "time_text.h"

namespace imudesk::format {

QString timeOfDayText(double secondsOfDay, int decimals)
{
    const int whole = int(secondsOfDay);
    return QStringLiteral("%1:%2:%3")
        .arg(whole / 3600, 2, 10, QLatin1Char('0'))
        .arg(whole / 60 % 60, 2, 10, QLatin1Char('0'))
        .arg(secondsOfDay - whole / 60 * 60, decimals + 3, 'f', decimals, QLatin1Char('0'));
}

} // namespace imudesk::format
