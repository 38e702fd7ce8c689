#pragma once
// Output rate against the link: bytes per second of the configured messages and the
// UART's capacity at 10 bits per byte (start, 8 data, stop). Frame sizes from the
// manuals: HI91 76, HI92 48, HI81 104 payload bytes and HI83 8 + its fields (v1.7.1 §5.9),
// plus the 6-byte frame header (5A A5, LEN, CRC). NMEA sentences are counted at the
// NMEA 0183 maximum of 82 characters (SXT, longer: 120, the limit ImuDesk accepts).
// The manuals' table of maximum rates (v1.7.1 §5.13, v1.6.6 §3.7) lists, per baud, the
// largest of the usual rates (1, 2, 5, 10, 20, 50, 100, 200, 250, 500, 1000 Hz) whose
// frames fit: HI91 at 115200 -> 100 Hz, at 921600 -> 1000 Hz.
#include "protocol/hipnuc/ascii_command.h"
#include "settings/device_configuration.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <vector>

namespace imudesk::settings {

class BandwidthCalculator {
    Q_DECLARE_TR_FUNCTIONS(BandwidthCalculator)

public:
    static constexpr double kBitsPerByte = 10.0;
    static constexpr double kTightLoad = 0.9; // above this a frame now and then is late or lost

    struct Stream {
        protocol::hipnuc::Message message = protocol::hipnuc::Message::HI91;
        double rateHz = 0;
        uint32_t hi83Map = 0x000000FFu;
    };
    struct Line {
        Stream stream;
        size_t frameBytes = 0;
        double bytesPerSecond = 0;
    };
    struct Result {
        std::vector<Line> lines;
        int baud = 0;
        double bytesPerSecond = 0;
        double capacityBytesPerSecond = 0;
        double load = 0;   // bytesPerSecond / capacity
        bool fits = true;  // load <= 1
        bool tight = false;
        QString warning;   // empty when it fits with margin
    };

    // The bytes one frame or sentence of the message takes on the wire.
    static size_t frameBytes(protocol::hipnuc::Message m, uint32_t hi83Map = 0x000000FFu);
    static double capacity(int baud) { return double(baud) / kBitsPerByte; }
    // The usual output rates (Hz) the tables use, ascending.
    static const std::vector<int> &rateClasses();
    // The largest usual rate whose frames the link carries (0 if not even 1 Hz).
    static int maxRateClass(protocol::hipnuc::Message m, int baud, uint32_t hi83Map = 0x000000FFu);
    static Result evaluate(const std::vector<Stream> &streams, int baud);
    // The periodic (ONTIME) outputs of a configuration at its SERIAL.BAUD, or at baud if > 0.
    static Result evaluate(const DeviceConfiguration &config, int baud = 0);
};

} // namespace imudesk::settings
