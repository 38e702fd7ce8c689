#pragma once
// The module check's report as JSON (imudesk-cli verify --json, the wizard's calibration
// history record, the station's step): the figures the issue names, each [x, y, z] or a
// number with a _sigma twin, null with a _why when not judged; the still intervals; the
// verdict and its reasons.
#include "verify/module_check.h"

#include <QJsonObject>

namespace imudesk::verify {

QJsonObject toJson(const CheckReport &report, const QString &source);

} // namespace imudesk::verify
