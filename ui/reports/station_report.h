#pragma once
// The report of one module's station run (issue 22), in the calibration report's style: the
// module (serial, product, firmware before and after, port), the plan, the verdict and for a
// failure the failing step with its values, then every step with its verdict, what it found
// and each measured value against its limit, and where the evidence recording is kept.
// QtGui only (QTextDocument, QPdfWriter): the CLI can write it without widgets.
#include "core/station/station_result.h"
#include "core/station/test_plan.h"

#include <QCoreApplication>
#include <QString>

namespace imudesk::ui {

class StationReport {
    Q_DECLARE_TR_FUNCTIONS(imudesk::ui::StationReport)

public:
    static QString html(const station::ModuleResult &module, const station::TestPlan &plan);
    // false with *error (translated).
    static bool writePdf(const station::ModuleResult &module, const station::TestPlan &plan, const QString &path,
                         QString *error);
};

// The runner's report writer (station::StationRunner::ReportWriter).
bool writeStationReport(const station::ModuleResult &module, const station::TestPlan &plan, const QString &path,
                        QString *error);

} // namespace imudesk::ui
