#pragma once
// A station's result of one module as the results database keeps it (issue 38). The station
// knows the database's record; core/results knows nothing of the station.
#include "core/results/result_record.h"
#include "core/station/station_result.h"

namespace imudesk::station {

// The station's result of one module in this run; artifacts hashed from the files it names.
results::ModuleRecord toResultRecord(const ModuleResult &r, const results::RunRecord &run);

} // namespace imudesk::station
