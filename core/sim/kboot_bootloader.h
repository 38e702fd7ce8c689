#pragma once
// The KBOOT serial bootloader of a simulated HiPNUC module, with its flash.
// Plain value class driven by HipnucSimulator: receive() queues host bytes with UART
// timing (a byte is complete 10 bit times after the previous one), runUntil() handles
// the bytes that have arrived by then, and takeOutput() returns the packets to send, in order.
//
// Protocol (hipnuc-protocol-notes.md 3.1-3.3): ping → ping response P2.0.0; every CRC-valid
// command is ACKed, then answered (GenericResponse, GetPropertyResponse, ReadMemoryResponse);
// a framed packet with a bad CRC is NAKed. The device does not need the host's ACK of a
// response (the HiPNUC hosts never send one) but ignores it when it comes (blhost does).
//   GetProperty    0x01 CurrentVersion K1.4.0, 0x03 flash start, 0x04 flash size, 0x05 sector size,
//                  0x0B max packet size, 0x10 bootloader version (109), 0x39 application version;
//                  others: kStatus_UnknownProperty.
//   FlashEraseRegion  address and length sector-aligned, inside the flash and not in the
//                  bootloader area; takes eraseUsPerSector per sector before the response.
//   WriteMemory    address word-aligned, range inside the application area; then data packets,
//                  each ACKed, until the length is reached, then the final GenericResponse. Writing
//                  a byte that is not erased (0xFF) ANDs it in and ends with kStatusMemoryCumulativeWrite.
//   ReadMemory     (unless disabled) ReadMemoryResponse, data packets of max packet size, each sent
//                  after the host's ACK of the previous one (NAK: sent again), then GenericResponse.
//   Reset          GenericResponse, then the module restarts (application if valid).
//   A ping or a command aborts an unfinished data phase.
//
// Flash: by default 512 KiB in 4 KiB sectors from address 0; the first 32 KiB are the
// bootloader, the application area starts at 0x8000. The application is valid when the last
// completed WriteMemory started at the application start and no erase touched it since; the
// module starts the application only when it is valid, else the bootloader.
// The application reports the version found in its image after kVersionMarker
// ("HIPNUC-SIM-APP_VER=1.7.2", NUL-terminated) as APP_VER.
//
// Fault injection for tests (each fires once, counted in data packets since entering the bootloader):
//   nakDataPacket N       data packet N is NAKed (its bytes are discarded)
//   silentDataPacket N    data packet N gets no ACK (and is discarded)
//   corruptAckDataPacket N  the ACK of data packet N is damaged (5A E1)
//   powerLossDataPacket N   power is lost when data packet N arrives (it is not written)
#include "protocol/kboot/packet_decoder.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::sim {

class KbootBootloader {
public:
    static constexpr const char *kVersionMarker = "HIPNUC-SIM-APP_VER=";
    static constexpr size_t kMaxRxQueue = 64 * 1024; // a UART FIFO + DMA ring; more is lost

    struct Options {
        uint32_t flashSize = 512 * 1024;
        uint32_t sectorSize = 4096;
        uint32_t appStart = 0x8000;
        uint32_t maxPacketSize = 512;
        uint32_t currentVersion = 0x4B010400; // "K1.4.0"
        uint32_t bootloaderVersion = 109;
        int64_t eraseUsPerSector = 1000;
        bool readMemory = true;
    };
    struct Faults {
        int nakDataPacket = 0;
        int silentDataPacket = 0;
        int corruptAckDataPacket = 0;
        int powerLossDataPacket = 0;
    };
    struct Stats {
        uint64_t pings = 0, commands = 0, dataPackets = 0, naksSent = 0, crcErrors = 0, bytesWritten = 0,
                 bytesRead = 0, sectorsErased = 0, rxOverruns = 0;
    };
    enum class Request { None, Reset, PowerLoss };

    explicit KbootBootloader(Options options);
    KbootBootloader() : KbootBootloader(Options{}) {}

    // Packets to send since the last call, in order.
    std::vector<std::vector<uint8_t>> takeOutput();
    // The bootloader starts (after a reset) at time t with the UART at baud.
    void start(int baud, int64_t t);
    void receive(const uint8_t *data, size_t n, int64_t t);
    // Earliest time runUntil() has something to do (INT64_MAX: nothing).
    int64_t nextEventUs() const;
    // Handles what is due at t; Reset/PowerLoss ask the module to restart.
    Request runUntil(int64_t t);

    const Options &options() const { return m_options; }
    // A bootloader without ReadMemory answers it with kStatus_UnknownCommand.
    void setReadMemoryEnabled(bool on) { m_options.readMemory = on; }
    Faults &faults() { return m_faults; }
    const Stats &stats() const { return m_stats; }
    const std::vector<uint8_t> &flash() const { return m_flash; }
    std::vector<uint8_t> applicationArea() const;
    bool applicationValid() const { return m_appValid; }
    // The version text after kVersionMarker in the application area, if any.
    std::optional<std::string> applicationVersion() const;
    // Programs an application image at appStart as a completed update would (tests, start-up).
    void installApplication(const std::vector<uint8_t> &image);

    // A deterministic pseudo-random application image of size bytes that carries the version marker.
    static std::vector<uint8_t> makeApplication(const std::string &version, size_t size, uint64_t seed = 1);
    // The version text after kVersionMarker in flash from offset `from` (an application image
    // made by makeApplication), if any; the simulated CAN bootloader reads its flash with it too.
    static std::optional<std::string> versionIn(const std::vector<uint8_t> &flash, size_t from);

private:
    struct RxByte {
        uint8_t value;
        int64_t atUs;
    };
    enum class Phase { Idle, WriteData, ReadData };

    void handle(const protocol::kboot::Packet &p, int64_t t);
    void handleCommand(const std::vector<uint8_t> &payload, int64_t t);
    void handleData(const std::vector<uint8_t> &payload);
    void sendPacket(const std::vector<uint8_t> &bytes);
    void sendResponse(const std::vector<uint8_t> &payload);
    void sendReadChunk();
    void finishWrite();

    Options m_options;
    Faults m_faults;
    Stats m_stats;
    std::vector<std::vector<uint8_t>> m_out;
    std::vector<uint8_t> m_flash;
    bool m_appValid = false;

    std::deque<RxByte> m_rx;
    double m_byteUs = 1e7 / 115200.0;
    int64_t m_rxFreeUs = 0;
    protocol::kboot::PacketDecoder m_decoder;

    Phase m_phase = Phase::Idle;
    int64_t m_busyUntilUs = 0;
    std::vector<uint8_t> m_deferred;  // response sent when busy ends (erase)
    uint32_t m_address = 0, m_remaining = 0, m_writeStart = 0;
    uint32_t m_writeStatus = 0;
    std::vector<uint8_t> m_lastChunk; // ReadMemory: the packet waiting for the host's ACK
    int m_dataPackets = 0;            // since start, for faults
    Request m_request = Request::None;
};

} // namespace imudesk::sim
