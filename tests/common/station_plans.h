#pragma once
// A short station plan for a simulated tray (tst_station_view, tst_station_session): identify
// (HI14, firmware at least 1.6.6), firmware at least 1.7.1 without an image (a module with 1.6.6
// fails it), static 2 s, attitude 1 s; a save step that is off in the plan (every tile says so).
#include "core/station/test_plan.h"

#include <QVariantMap>

namespace imudesk::test {

inline station::TestPlan shortTrayPlan(const QString &name)
{
    using station::StepKind;
    station::TestPlan plan;
    plan.name = name;
    auto add = [&plan](StepKind kind, QVariantMap params = {}) {
        plan.steps.push_back(station::TestPlan::defaultStep(kind, params));
    };
    add(StepKind::Identify, {{QStringLiteral("products"), QStringLiteral("HI14")},
                             {QStringLiteral("firmware_min"), QStringLiteral("1.6.6")}});
    add(StepKind::Firmware, {{QStringLiteral("minimum"), QStringLiteral("1.7.1")}, {QStringLiteral("image"), QString()}});
    add(StepKind::Static, {{QStringLiteral("seconds"), 2.0}});
    add(StepKind::Attitude, {{QStringLiteral("seconds"), 1.0}});
    add(StepKind::Save);
    plan.steps.back().enabled = false;
    return plan;
}

} // namespace imudesk::test
