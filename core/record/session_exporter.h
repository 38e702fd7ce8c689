#pragma once
// Exports a recorded session (a folder with session.json, record/group_recording.h) as one
// file with the devices aligned on the common time (issue 36 points 3 and 7):
//   * tidy CSV / JSON Lines: every sample of every device, in the order of its aligned time
//     (its common time plus the device's offset from twist-to-align; its arrival where it has no
//     common time), with a device column (key) before the capture's own columns (keys);
//   * a grid (gridMs > 0): one row per instant of a regular grid over the time all devices were
//     recording, each device's acceleration, rate and attitude interpolated linearly between
//     its two samples around the instant (blank where it has none within maxGapMs);
//   * trigger pairs (pulseHz > 0, hardware trigger mode): modules that sent a frame at each
//     SYNC_IN edge (LOG ... ONMARK 1): one row per pulse, each device's frame of that pulse
//     (clock::TriggerPairing: by the device's counter, the devices' counts tied together by the
//     common times of their frames from 2 s in, once their clock models are aligned). One frame
//     type a device: the first with a device time (the other types count on other clocks).
// The merge is by each sample's key as it comes; a stream whose key steps back (the clock model's
// first refits, a compass's own output between its answers) is merged as it comes, so the order
// is exact to within the stream's own steps back (at most an adapter's latency).
// Devices whose link ImuDesk does not decode from a capture (CAN, Modbus) are left out, with a note.
// The devices are read side by side, a sample at a time: memory does not grow with the session.
#include "record/capture_exporter.h"
#include "record/session_manifest.h"

#include <QCoreApplication>
#include <QString>

#include <functional>

namespace imudesk::record {

class SessionExporter {
    Q_DECLARE_TR_FUNCTIONS(SessionExporter)

public:
    struct Options {
        CaptureExporter::Format format = CaptureExporter::Format::TidyCsv; // not VendorCsv
        QString output;
        double gridMs = 0;    // > 0: resample onto this grid (tidy CSV only)
        double maxGapMs = 50; // grid: no value where a device's samples are further apart
        double pulseHz = 0;   // > 0: pair the triggered frames by pulse (tidy CSV only)
        std::function<bool()> cancelled; // asked now and then; true: stop (the output is removed)
    };
    struct Result {
        bool ok = false;
        QString error;
        uint64_t rows = 0;
        std::vector<uint64_t> samplesByDevice;
        int64_t pulses = 0, pulsesComplete = 0; // trigger pairs: pulses seen, pulses every device has
        QStringList notes; // e.g. devices that dropped out
    };
    static Result run(const QString &folder, const Options &options);
};

} // namespace imudesk::record
