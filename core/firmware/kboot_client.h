#pragma once
// The host side of KBOOT over a ByteLink: one transaction at a time, every reply checked
// (type, CRC, tag, parameter count, status, command echo), timeouts from
// hipnuc-protocol-notes.md 3.3. Errors are returned as text that says what happened and
// what to do; lastStatus() keeps the bootloader's status code of the last response.
//
// Exchange: command → ACK → response (the host does not ACK responses, as the HiPNUC hosts;
// during ReadMemory it ACKs the ReadMemoryResponse and every data packet, as KBOOT requires).
// A NAK'd command or data packet is sent again, up to Timeouts::maxRetries times; a data
// packet whose ACK does not come is not sent again (KBOOT has no sequence numbers, a second
// copy could be written twice): the transfer fails and the update must be run again.
#include "io/byte_link.h"
#include "protocol/kboot/command.h"
#include "protocol/kboot/packet_decoder.h"

#include <QCoreApplication>
#include <QString>

#include <deque>
#include <functional>
#include <optional>

namespace imudesk::firmware {

class KbootClient {
    Q_DECLARE_TR_FUNCTIONS(KbootClient)

public:
    struct Timeouts {
        int pingWindowMs = 100;
        int pingPauseMs = 100;
        // A command's ACK and response, and each data packet's ACK or arrival: 5 s, blhost's
        // default serial timeout. A host whose tty worker thread is held up (a busy machine:
        // up to 3.3 s measured beside two busy loops, see io/reading_priority.h) is not a dead
        // bootloader; a dead one is still named within seconds.
        int commandMs = 5000;
        int eraseMs = 10000;
        int dataAckMs = 5000;
        int maxRetries = 3;
    };
    struct Counters {
        uint64_t commands = 0, dataPackets = 0, naks = 0, resent = 0;
    };
    // Called after each acknowledged data packet with the bytes done; false cancels.
    using Progress = std::function<bool(uint64_t done)>;

    KbootClient(ByteLink &link, Timeouts timeouts);
    explicit KbootClient(ByteLink &link) : KbootClient(link, Timeouts{}) {}

    // Sends a ping up to attempts times; the ping response's version in *version.
    bool ping(int attempts, protocol::kboot::PingResponse *version, QString *error);
    std::optional<uint32_t> getProperty(protocol::kboot::PropertyTag tag, QString *error);
    bool flashEraseRegion(uint32_t address, uint32_t length, int timeoutMs, QString *error);
    bool writeMemory(uint32_t address, const uint8_t *data, size_t size, size_t packetSize, const Progress &progress,
                     QString *error);
    bool readMemory(uint32_t address, size_t size, std::vector<uint8_t> &out, const Progress &progress, QString *error);
    bool reset(QString *error);

    uint32_t lastStatus() const { return m_lastStatus; }
    bool cancelled() const { return m_cancelled; }
    const Counters &counters() const { return m_counters; }
    const protocol::kboot::PacketDecoder::Counters &decoderCounters() const { return m_decoder.counters(); }
    const Timeouts &timeouts() const { return m_timeouts; }

private:
    void flushInput();
    // The next packet within timeoutMs; nullopt on timeout or transport error (*error set).
    std::optional<protocol::kboot::Packet> nextPacket(int timeoutMs, QString *error);
    // Sends a command and waits for its ACK (a NAK resends it).
    bool sendCommand(const protocol::kboot::Command &c, QString *error);
    // Waits for the response with the given tag; checks the status.
    std::optional<protocol::kboot::Command> response(protocol::kboot::CommandTag tag, uint8_t echo, int timeoutMs,
                                                     QString *error);
    bool write(const std::vector<uint8_t> &bytes, QString *error);
    QString describeSilence(const QString &what) const;

    ByteLink &m_link;
    Timeouts m_timeouts;
    protocol::kboot::PacketDecoder m_decoder;
    std::deque<protocol::kboot::Packet> m_packets;
    Counters m_counters;
    uint32_t m_lastStatus = 0;
    bool m_cancelled = false;
    uint64_t m_damageMark = 0;
};

} // namespace imudesk::firmware
