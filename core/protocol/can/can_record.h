#pragma once
// CAN frames as a byte stream: how a CAN interface (io::CanTransport) hands frames to the
// session engine, which moves bytes whatever the link (raw-byte log, recording, the family's
// decoder). One record per frame, little-endian:
//   [0]    flags: bit 0 extended (29-bit) identifier, bit 1 CAN FD, bit 2 remote, bit 3 error frame
//   [1]    data length, 0..64
//   [2..5] identifier
//   [6..]  the data bytes
// With flag bit 4 (stamped) eight bytes come before the data: the interface's receive stamp
// (the kernel's, for SocketCAN) in ns on the host clock (clock::hostNowNs), little-endian.
// A record whose length byte exceeds 64 or whose flags have unknown bits set is not a record:
// the reader skips one byte and looks again (counted).
#include "protocol/can/can_frame.h"

#include <QByteArray>

#include <cstdint>
#include <vector>

namespace imudesk::protocol::can {

struct CanRecord {
    CanFrame frame;
    bool error = false; // an error frame reported by the interface
    int64_t stampNs = 0; // the interface's receive stamp on the host clock; 0: none
};

QByteArray toRecord(const CanFrame &f, bool errorFrame = false, int64_t stampNs = 0);
// The time a frame takes on the bus at bitrate (bit/s; FD frames at their arbitration rate,
// a bound): its bits with the usual share of stuff bits. 0 when the bitrate is not known.
int64_t wireTimeNs(const CanFrame &f, int bitrate);

class CanRecordReader {
public:
    static constexpr int kHeader = 6;

    // Appends every whole record in bytes (and in what was held before) to out.
    void feed(const QByteArray &bytes, std::vector<CanRecord> &out);
    bool holding() const { return !m_held.isEmpty(); }
    void reset() { m_held.clear(); }
    uint64_t bytesSkipped() const { return m_skipped; }

private:
    QByteArray m_held;
    uint64_t m_skipped = 0;
};

} // namespace imudesk::protocol::can
