#pragma once
// session.json: what ties the captures of one multi-device recording together (issue 36).
//
//   {"format": "imudesk-session", "version": 1,
//    "started_utc": "2026-11-29T19:30:00.123Z", "started_host_ns": 123456789, "stopped_host_ns": ...,
//    "devices": [
//      {"name": "A", "address": "/dev/ttyUSB0", "link_kind": "HiPNUC serial", "file": "A.imucap",
//       "product": "HI14R3", "serial": "...", "firmware": "1.7.1",
//       "bytes": 123, "frames": 456,
//       "offset_ns": 0,            // added to the device's common times (twist to align)
//       "offset_method": "",       // "twist" when set by twist-to-align
//       "clocks": [{"source": "HI91", "method": "counter", "state": "aligned", "drift_ppm": 40.0,
//                   "jitter_ns": 48000, "uncertainty_ns": 0, "resets": 0}],
//       "events": [{"host_ns": 1234, "what": "disconnected", "detail": "..."}]}]}
//
// Host times are the recording host's steady clock (clock::hostNowNs), the clock of every
// capture's chunks and of the common times: the devices are aligned on it.
#include "device/session_types.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace imudesk::record {

struct SessionManifest {
    static constexpr const char *kFileName = "session.json";
    static constexpr const char *kFormat = "imudesk-session";
    static constexpr int kVersion = 1;

    struct Event {
        int64_t hostNs = 0;
        QString what;   // "disconnected", "reconnected", "recording stopped"
        QString detail;
    };
    struct Device {
        QString name, address, linkKind, file;
        QString product, serial, firmware;
        quint64 bytes = 0, frames = 0;
        double offsetNs = 0;
        QString offsetMethod;
        std::vector<device::ClockStats> clocks;
        std::vector<Event> events;
        bool droppedOut() const;
    };
    QString startedUtc;
    int64_t startedHostNs = 0, stoppedHostNs = 0;
    std::vector<Device> devices;

    QByteArray toJson() const;
    // false with a message on a file that is not a session manifest.
    static bool fromJson(const QByteArray &json, SessionManifest *out, QString *error);
    bool save(const QString &folder, QString *error) const;
    static bool load(const QString &folder, SessionManifest *out, QString *error);
    // A folder with a session.json.
    static bool isSessionFolder(const QString &path);
};

const char *clockMethodName(device::ClockStats::Method m);     // "counter", "bracket", "stamp"
const char *clockStateName(clock::ClockModel::State s);        // "aligned", "uncertain", "free-running"

} // namespace imudesk::record
