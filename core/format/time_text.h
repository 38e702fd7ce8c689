#pragma once
// A time of day as people read it: "hh:mm:ss" with `decimals` digits of the second
// ("13:05:07.25"), zero-padded. The values table and the CLI's text lines share it.
#include <QString>

namespace imudesk::format {

QString timeOfDayText(double secondsOfDay, int decimals);

} // namespace imudesk::format
