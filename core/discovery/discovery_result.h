#pragma once
// What one sweep of a bench found (bench_sweep.h): the devices with the link each answers on,
// the conflicts (two devices at one address of one bus) with what showed them, and a note for
// every port or bus where nothing answered (busy, silent, garbage). Plain values: the CLI
// prints them, the window lists them, a test compares them.
#include <QJsonObject>
#include <QList>
#include <QString>

namespace imudesk::discovery {

struct FoundDevice {
    enum class Link { Serial, Modbus, Can };
    Link link = Link::Serial;
    QString port;        // serial or Modbus: the port; CAN: PLUGIN:INTERFACE
    int baud = 0;        // serial and Modbus
    int bitrate = 0;     // CAN: the bus's bit rate (0: not known, bitrateWhy says why)
    QString bitrateWhy;
    QString family;      // "hipnuc", "hec495" (serial); "hipnuc-modbus", "hec495-modbus"; "j1939", "canopen", "hec495-can"
    QString model;       // product name, empty when not read
    QString serial;      // serial number, empty when not read
    QString firmware;    // firmware version, empty when not read
    int address = -1;    // a serial device's bus address, a Modbus id (-1: none)
    int node = -1;       // CAN: node ID or J1939 source address (-1: none)
    QString note;        // what else was seen ("streams HI91 at 100 Hz", "identity not answered")

    // "serial", "modbus", "can"
    static QString linkId(Link l);
    QJsonObject toJson() const;
};

struct Conflict {
    QString port;       // the bus: serial port or PLUGIN:INTERFACE
    QString link;       // "modbus", "can"
    int address = -1;   // the address or node both answer to
    QString evidence;   // what was seen, translated
    QString advice;     // what to do, translated
    QJsonObject toJson() const;
};

// A port or bus where no device was found, and why.
struct PortNote {
    enum class Kind { Busy, Silent, Garbage, NoPermission, Failed, OutOfTime, Cancelled };
    QString port;
    Kind kind = Kind::Silent;
    QString text;  // translated: what happened and what to do
    static QString kindId(Kind k); // "busy", "silent", ...
    QJsonObject toJson() const;
};

struct SweepResult {
    QList<FoundDevice> devices;
    QList<Conflict> conflicts;
    QList<PortNote> notes;
    double seconds = 0;
    bool cancelled = false;
    // 0: something found and no conflict; 1: a conflict; 2: nothing found (imudesk-cli discover).
    int exitCode() const;
    QJsonObject toJson() const;
    // One line per device, conflict and note, for a terminal.
    QStringList textLines() const;
};

} // namespace imudesk::discovery
