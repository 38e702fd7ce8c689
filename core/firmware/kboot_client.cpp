#include "kboot_client.h"

#include "protocol/kboot/status_code.h"

#include <QLoggingCategory>

#include <algorithm>

namespace imudesk::firmware {

namespace {
Q_LOGGING_CATEGORY(lcKboot, "imudesk.core.firmware.kboot", QtInfoMsg)
}

using namespace protocol::kboot;

KbootClient::KbootClient(ByteLink &link, Timeouts timeouts) : m_link(link), m_timeouts(timeouts) {}

void KbootClient::flushInput()
{
    m_link.clearInput();
    m_packets.clear();
    m_decoder.reset();
}

bool KbootClient::write(const std::vector<uint8_t> &bytes, QString *error)
{
    return m_link.write(bytes, error);
}

std::optional<Packet> KbootClient::nextPacket(int timeoutMs, QString *error)
{
    const int64_t deadline = m_link.nowUs() + int64_t(timeoutMs) * 1000;
    std::vector<uint8_t> buf;
    for (;;) {
        if (!m_packets.empty()) {
            Packet p = std::move(m_packets.front());
            m_packets.pop_front();
            return p;
        }
        const int64_t left = deadline - m_link.nowUs();
        if (left <= 0)
            return std::nullopt;
        buf.clear();
        if (!m_link.read(buf, int(std::max<int64_t>(1, left / 1000)), error))
            return std::nullopt;
        if (!buf.empty())
            for (auto &p : m_decoder.feed(buf))
                m_packets.push_back(std::move(p));
    }
}

QString KbootClient::describeSilence(const QString &what) const
{
    const auto &c = m_decoder.counters();
    const uint64_t damage = c.bytesSkipped + c.crcErrors + c.lengthErrors;
    if (damage > m_damageMark)
        return tr("%1: only damaged bytes arrived (%2 bytes skipped, %3 CRC errors); the line is noisy or the baud "
                  "is wrong. Run the update again")
            .arg(what)
            .arg(c.bytesSkipped)
            .arg(c.crcErrors);
    return tr("%1: the bootloader did not answer; check the cable and power, then run the update again").arg(what);
}

bool KbootClient::ping(int attempts, PingResponse *version, QString *error)
{
    // Input is cleared before the first ping only: an answer that arrives after its window
    // (a busy host, a USB adapter's latency) still shows that a bootloader is there, so it
    // counts while a later ping waits.
    flushInput();
    for (int i = 0; i < attempts; ++i) {
        if (!write(encodePing(), error))
            return false;
        const int64_t deadline = m_link.nowUs() + int64_t(m_timeouts.pingWindowMs) * 1000;
        while (m_link.nowUs() < deadline) {
            QString e;
            const auto p = nextPacket(int((deadline - m_link.nowUs()) / 1000) + 1, &e);
            if (!e.isEmpty()) {
                if (error)
                    *error = e;
                return false;
            }
            if (!p)
                break;
            if (p->type == PacketType::PingResponse) {
                if (version)
                    *version = p->ping;
                return true;
            }
        }
        if (i + 1 < attempts)
            m_link.sleepMs(m_timeouts.pingPauseMs);
    }
    if (error)
        *error = tr("no bootloader answered %1 pings; check the port and baud rate, power-cycle the module and run "
                    "the update again")
                     .arg(attempts);
    return false;
}

bool KbootClient::sendCommand(const Command &c, QString *error)
{
    m_lastStatus = kStatusSuccess;
    flushInput();
    const auto bytes = encodeFramed(PacketType::Command, c.encode());
    ++m_counters.commands;
    const QString what = tr("command 0x%1").arg(c.tag, 2, 16, QLatin1Char('0'));
    for (int attempt = 0; attempt <= m_timeouts.maxRetries; ++attempt) {
        if (!write(bytes, error))
            return false;
        m_damageMark = m_decoder.counters().bytesSkipped + m_decoder.counters().crcErrors
            + m_decoder.counters().lengthErrors;
        for (;;) {
            QString e;
            const auto p = nextPacket(m_timeouts.commandMs, &e);
            if (!p) {
                if (error)
                    *error = e.isEmpty() ? describeSilence(tr("no ACK for %1").arg(what)) : e;
                return false;
            }
            if (p->type == PacketType::Ack)
                return true;
            if (p->type == PacketType::Nak) {
                ++m_counters.naks;
                ++m_counters.resent;
                break; // send again
            }
            if (p->type == PacketType::AckAbort) {
                if (error)
                    *error = tr("the bootloader aborted %1").arg(what);
                return false;
            }
            // anything else (a late reply of an earlier exchange) is not ours: keep waiting
        }
    }
    if (error)
        *error = tr("the bootloader refused %1 %2 times (NAK: damaged on the way); check the cable")
                     .arg(what)
                     .arg(m_timeouts.maxRetries + 1);
    return false;
}

std::optional<Command> KbootClient::response(CommandTag tag, uint8_t echo, int timeoutMs, QString *error)
{
    const QString what = tr("response to command 0x%1").arg(echo, 2, 16, QLatin1Char('0'));
    const int64_t deadline = m_link.nowUs() + int64_t(timeoutMs) * 1000;
    for (;;) {
        QString e;
        const int64_t left = deadline - m_link.nowUs();
        const auto p = left > 0 ? nextPacket(int(left / 1000) + 1, &e) : std::nullopt;
        if (!p) {
            if (error)
                *error = e.isEmpty() ? describeSilence(tr("no %1 within %2 ms").arg(what).arg(timeoutMs)) : e;
            return std::nullopt;
        }
        if (p->type != PacketType::Command)
            continue;
        const auto c = Command::decode(p->payload);
        if (!c || c->params.size() < 2) {
            if (error)
                *error = tr("malformed %1").arg(what);
            return std::nullopt;
        }
        m_lastStatus = c->params[0];
        if (c->tag == uint8_t(CommandTag::GenericResponse) && tag != CommandTag::GenericResponse) {
            // A GenericResponse instead of the specific one: an error status for our command.
            if (c->params[1] != echo) {
                if (error)
                    *error = tr("the bootloader answered command 0x%1 instead of 0x%2")
                                 .arg(c->params[1], 2, 16, QLatin1Char('0'))
                                 .arg(echo, 2, 16, QLatin1Char('0'));
                return std::nullopt;
            }
            if (error)
                *error = tr("the bootloader refused command 0x%1: %2")
                             .arg(echo, 2, 16, QLatin1Char('0'))
                             .arg(KbootStatus::message(m_lastStatus));
            return std::nullopt;
        }
        if (c->tag != uint8_t(tag)) {
            if (error)
                *error = tr("unexpected response 0x%1 to command 0x%2")
                             .arg(c->tag, 2, 16, QLatin1Char('0'))
                             .arg(echo, 2, 16, QLatin1Char('0'));
            return std::nullopt;
        }
        if (tag == CommandTag::GenericResponse && c->params[1] != echo) {
            if (error)
                *error = tr("the bootloader answered command 0x%1 instead of 0x%2")
                             .arg(c->params[1], 2, 16, QLatin1Char('0'))
                             .arg(echo, 2, 16, QLatin1Char('0'));
            return std::nullopt;
        }
        if (m_lastStatus != kStatusSuccess) {
            if (error)
                *error = tr("the bootloader refused command 0x%1: %2")
                             .arg(echo, 2, 16, QLatin1Char('0'))
                             .arg(KbootStatus::message(m_lastStatus));
            return std::nullopt;
        }
        return c;
    }
}

std::optional<uint32_t> KbootClient::getProperty(PropertyTag tag, QString *error)
{
    if (!sendCommand(protocol::kboot::getProperty(tag), error))
        return std::nullopt;
    const auto r = response(CommandTag::GetPropertyResponse, uint8_t(CommandTag::GetProperty), m_timeouts.commandMs,
                            error);
    if (!r)
        return std::nullopt;
    return r->params[1];
}

bool KbootClient::flashEraseRegion(uint32_t address, uint32_t length, int timeoutMs, QString *error)
{
    if (!sendCommand(protocol::kboot::flashEraseRegion(address, length), error))
        return false;
    return response(CommandTag::GenericResponse, uint8_t(CommandTag::FlashEraseRegion), timeoutMs, error).has_value();
}

bool KbootClient::writeMemory(uint32_t address, const uint8_t *data, size_t size, size_t packetSize,
                              const Progress &progress, QString *error)
{
    m_cancelled = false;
    if (!sendCommand(protocol::kboot::writeMemory(address, uint32_t(size)), error))
        return false;
    if (!response(CommandTag::GenericResponse, uint8_t(CommandTag::WriteMemory), m_timeouts.commandMs, error))
        return false;
    size_t done = 0;
    uint64_t packetNo = 0;
    while (done < size) {
        const size_t n = std::min(packetSize, size - done);
        const auto bytes = encodeFramed(PacketType::Data, data + done, n);
        ++packetNo;
        bool acked = false;
        for (int attempt = 0; attempt <= m_timeouts.maxRetries && !acked; ++attempt) {
            if (attempt > 0) {
                ++m_counters.resent;
                qCInfo(lcKboot) << "resending data packet" << packetNo << "after a NAK";
            }
            if (!write(bytes, error))
                return false;
            ++m_counters.dataPackets;
            const auto &dc = m_decoder.counters();
            m_damageMark = dc.bytesSkipped + dc.crcErrors + dc.lengthErrors;
            for (;;) {
                QString e;
                const auto p = nextPacket(m_timeouts.dataAckMs, &e);
                const QString where = tr("data packet %1 (bytes %2..%3 at 0x%4)")
                                          .arg(packetNo)
                                          .arg(done)
                                          .arg(done + n - 1)
                                          .arg(address + done, 8, 16, QLatin1Char('0'));
                if (!p) {
                    if (error)
                        *error = e.isEmpty() ? describeSilence(tr("no ACK for %1").arg(where)) : e;
                    return false;
                }
                if (p->type == PacketType::Ack) {
                    acked = true;
                    break;
                }
                if (p->type == PacketType::Nak) {
                    ++m_counters.naks;
                    break;
                }
                if (p->type == PacketType::AckAbort) {
                    QString detail;
                    response(CommandTag::GenericResponse, uint8_t(CommandTag::WriteMemory), 200, &detail);
                    if (error)
                        *error = tr("the bootloader aborted the transfer at %1: %2").arg(where, detail);
                    return false;
                }
                if (p->type == PacketType::Command) {
                    // An early final response: the bootloader gave up on the write.
                    const auto c = Command::decode(p->payload);
                    if (error)
                        *error = tr("the bootloader ended the transfer at %1: %2")
                                     .arg(where, KbootStatus::message(c && !c->params.empty() ? c->params[0] : 1));
                    return false;
                }
            }
        }
        if (!acked) {
            if (error)
                *error = tr("data packet %1 was refused %2 times (NAK); the line is damaging data. Check the cable "
                            "and run the update again")
                             .arg(packetNo)
                             .arg(m_timeouts.maxRetries + 1);
            return false;
        }
        done += n;
        if (progress && !progress(done) && done < size) {
            m_cancelled = true;
            if (error)
                *error = tr("cancelled after %1 of %2 bytes").arg(done).arg(size);
            return false;
        }
    }
    return response(CommandTag::GenericResponse, uint8_t(CommandTag::WriteMemory), m_timeouts.dataAckMs, error)
        .has_value();
}

bool KbootClient::readMemory(uint32_t address, size_t size, std::vector<uint8_t> &out, const Progress &progress,
                             QString *error)
{
    m_cancelled = false;
    out.clear();
    if (!sendCommand(protocol::kboot::readMemory(address, uint32_t(size)), error))
        return false;
    const auto r = response(CommandTag::ReadMemoryResponse, uint8_t(CommandTag::ReadMemory), m_timeouts.commandMs,
                            error);
    if (!r)
        return false;
    if (r->params[1] != size) {
        if (error)
            *error = tr("the bootloader offers %1 bytes instead of %2").arg(r->params[1]).arg(size);
        return false;
    }
    out.reserve(size);
    if (!write(encodeControl(PacketType::Ack), error))
        return false;
    while (out.size() < size) {
        QString e;
        const auto &dc = m_decoder.counters();
        m_damageMark = dc.bytesSkipped + dc.crcErrors + dc.lengthErrors;
        const auto p = nextPacket(m_timeouts.dataAckMs, &e);
        if (!p) {
            if (error)
                *error = e.isEmpty() ? describeSilence(tr("reading back stopped after %1 of %2 bytes").arg(out.size()).arg(size))
                                     : e;
            return false;
        }
        if (p->type != PacketType::Data)
            continue;
        const size_t n = std::min(p->payload.size(), size - out.size());
        out.insert(out.end(), p->payload.begin(), p->payload.begin() + long(n));
        if (!write(encodeControl(PacketType::Ack), error))
            return false;
        if (progress && !progress(out.size()) && out.size() < size) {
            m_cancelled = true;
            write(encodeControl(PacketType::AckAbort), nullptr);
            if (error)
                *error = tr("cancelled while reading back");
            return false;
        }
    }
    return response(CommandTag::GenericResponse, uint8_t(CommandTag::ReadMemory), m_timeouts.commandMs, error)
        .has_value();
}

bool KbootClient::reset(QString *error)
{
    if (!sendCommand(protocol::kboot::reset(), error))
        return false;
    return response(CommandTag::GenericResponse, uint8_t(CommandTag::Reset), m_timeouts.commandMs, error).has_value();
}

} // namespace imudesk::firmware
