#pragma once
// Samples into a MATLAB .mat file (version 5, format/mat/mat_file.h): one struct per device,
// named after its serial number (or its session name), with
//   time_common   s      the sample's common time (the clock model's), NaN where it has none
//   time_device   s      the device's own clock (system_time), NaN where the frame has none
//   time_arrival  s      arrival on the host
//   (all three counted from the same origin: info.time_origin_utc, info.time_origin_unix_ns)
//   time_common_uncertainty s
//   main_status   1      MAIN_STATUS
//   acc           m/s^2  x y z        gyr  rad/s  x y z        mag  T  x y z
//   euler         rad    roll pitch yaw                    quat 1  w x y z
//   pressure      Pa     temperature  degC
//   position      deg, deg, m  lat lon alt                 vel  m/s  e n u
// and units, columns and info (product, serial, firmware, link, world frame, ...) beside them:
// one row per sample, NaN where the sample lacks the quantity. What File > Export and
// `imudesk-cli export --format mat` write, for a capture and for a recorded session.
#include "format/mat/mat_file.h"
#include "model/sample.h"
#include "capture/capture_header.h"

#include <QString>

#include <vector>

namespace imudesk::record {

class MatExport {
public:
    // originNs: the host time the three time vectors count from; epochOffsetNs: host clock to
    // the Unix epoch (0: unknown).
    MatExport(int64_t originNs, int64_t epochOffsetNs);
    // A device's struct, named capture::matlabDeviceName(header, label) ("SN_0042"; _2, _3, ...
    // when another has that name); -1 when it cannot be made (error()).
    int addDevice(const capture::CaptureHeader &header, const std::string &label = {});
    bool append(int device, const model::Sample &s);
    // Writes the file; false with error() (the file is not left behind).
    bool write(const QString &path);
    QString error() const { return m_file.error(); }
    uint64_t rows(int device) const { return m_file.rows(device); }

private:
    format::mat::MatFile m_file;
    int64_t m_originNs, m_epochOffsetNs;
    std::vector<double> m_row;
};

} // namespace imudesk::record
