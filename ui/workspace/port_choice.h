#pragma once
// One entry of the connection bar's port list: a serial port, or a simulated device
// that runs in-process behind a pseudo-terminal.
#include <QString>

namespace imudesk::ui {

struct PortChoice {
    enum class Kind { None, Serial, Simulated };
    Kind kind = Kind::None;
    QString port;      // Serial: system location, e.g. /dev/ttyUSB0
    QString model;     // Simulated: product model, e.g. HI14
    QString firmware;  // Simulated: firmware version, e.g. 1.7.1

    static PortChoice serial(const QString &port) { return {Kind::Serial, port, {}, {}}; }
    static PortChoice simulated(const QString &model, const QString &firmware)
    {
        return {Kind::Simulated, {}, model, firmware};
    }

    bool isValid() const { return kind != Kind::None; }
    // Stable text for settings and combo data: "serial:/dev/ttyUSB0", "sim:HI14:1.7.1".
    QString key() const;
    static PortChoice fromKey(const QString &key);
    friend bool operator==(const PortChoice &, const PortChoice &) = default;
};

// A simulated device a family offers in the connection bar (FamilyUi::simulatedDevices).
struct SimulatedDevice {
    PortChoice choice; // PortChoice::simulated(model, firmware)
    QString text;      // the entry's text, translated
};

} // namespace imudesk::ui
