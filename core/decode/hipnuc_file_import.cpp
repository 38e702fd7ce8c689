#include "hipnuc_file_import.h"

#include "decode/hipnuc_stream_decoder.h"
#include "decode/hipnuc_vendor_csv.h"
#include "decode/hipnuc_vendor_csv_reader.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/nmea/nmea_sample.h"
#include "protocol/stream/stream_demux.h"

#include <QByteArray>
#include <QFile>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace imudesk::decode {

namespace {

namespace hp = protocol::hipnuc;

// The device's clock as seen in a raw dump, as ns since its first stamp. One source is
// followed at a time, so that two clocks never alternate: the best one seen so far, by rank.
// The module's own counter (HI91 system_time, HI83 system_time_us) ranks first; a GNSS time of
// week (HI81: 0 until the receiver has a fix, so it may never move) second; NMEA's UTC last.
// When a better source appears, the times go on from where they were on its clock. A jump
// back of more than a second, or forward of more than ten (a restart, the UTC alignment,
// midnight in NMEA time), is carried across the same way.
class DeviceClock {
public:
    void frameTime(const std::string &source, double ms) { offer(source, source == "HI81" ? 1 : 2, ms); }
    void nmeaTime(double ms) { offer("NMEA", 0, ms); }
    bool known() const { return m_rank >= 0; }
    int64_t ns() const { return known() ? int64_t((m_baseMs + m_lastMs - m_firstMs) * 1e6) : 0; }
    uint64_t jumps() const { return m_jumps; }

private:
    void offer(const std::string &source, int rank, double ms)
    {
        if (rank > m_rank) {
            // A better clock: it starts here, at the time reached so far.
            m_baseMs = known() ? m_baseMs + m_lastMs - m_firstMs : 0.0;
            m_source = source;
            m_rank = rank;
            m_firstMs = m_lastMs = ms;
            return;
        }
        if (source != m_source)
            return;
        const double d = ms - m_lastMs;
        if (d < -1000.0 || d > 10000.0) {
            m_baseMs += m_lastMs - m_firstMs;
            m_firstMs = ms;
            ++m_jumps;
        }
        m_lastMs = ms;
    }

    std::string m_source;
    int m_rank = -1;
    double m_baseMs = 0, m_firstMs = 0, m_lastMs = 0;
    uint64_t m_jumps = 0;
};

// Feeds bytes through the live session's demultiplexer and reports what they held.
struct Scan {
    protocol::StreamDemux demux;
    std::vector<protocol::StreamEvent> events;
    uint64_t frames = 0, sentences = 0;

    void feed(const uint8_t *data, size_t n, DeviceClock *clock)
    {
        events.clear();
        demux.feed(data, n, events);
        take(clock);
    }
    void finish(DeviceClock *clock)
    {
        events.clear();
        demux.finish(events);
        take(clock);
    }
    void take(DeviceClock *clock)
    {
        for (const auto &e : events) {
            if (e.kind == protocol::StreamEvent::Kind::Frame) {
                ++frames;
                if (clock)
                    hp::forEachPacket(e.payload, [&](const hp::Packet &p) {
                        const model::Sample s = hp::toSample(p);
                        if (s.has(model::FieldDeviceTime))
                            clock->frameTime(s.source, s.deviceTimeMs);
                    });
            } else if (e.kind == protocol::StreamEvent::Kind::Nmea) {
                ++sentences;
                if (clock)
                    if (const auto s = protocol::nmea::sampleOf(e.text); s && s->utcTimeOfDayS >= 0)
                        clock->nmeaTime(s->utcTimeOfDayS * 1000.0);
            }
        }
    }
};

} // namespace

// --- the vendor's CSV -----------------------------------------------------------------------

const char *HipnucVendorCsvImport::family() const
{
    return HipnucStreamDecoder::kFamily;
}

bool HipnucVendorCsvImport::recognises(const QByteArray &head, bool) const
{
    return head.startsWith("HI91,");
}

QString HipnucVendorCsvImport::looksLike() const
{
    return tr("a vendor CSV (first line \"HI91,...\")");
}

FileImporter::Result HipnucVendorCsvImport::convert(const QString &path, ChunkSink &out) const
{
    Result r;
    const std::vector<std::string> layout = vendor_csv::hi91Names();
    const auto read = VendorCsvImporter::readRows(path, [&](const model::Sample &s, const VendorCsvImporter::Row &row) {
        hp::Hi91 h;
        h.temperature = int8_t(std::lround(std::clamp(s.temperatureC, -128.0, 127.0)));
        h.pressure = float(s.pressurePa);
        h.systemTime = uint32_t(std::max(0.0, s.deviceTimeMs));
        h.acc = {float(s.acc.x), float(s.acc.y), float(s.acc.z)};
        h.gyr = {float(s.gyr.x), float(s.gyr.y), float(s.gyr.z)};
        h.mag = {float(s.mag.x), float(s.mag.y), float(s.mag.z)};
        h.roll = float(s.roll);
        h.pitch = float(s.pitch);
        h.yaw = float(s.yaw);
        h.quat = {float(s.quat.w), float(s.quat.x), float(s.quat.y), float(s.quat.z)};
        // Every cell the export would not write as the file has it (pps_sync_stamp, incli_x,
        // incli_y: HI91 has no such field; a norm or a time written otherwise) goes into the
        // capture beside the frame.
        const std::vector<std::string> again = vendor_csv::hi91Cells(h, double(s.hostTimeNs) / 1e6);
        vendor_csv::Cells keep;
        for (size_t i = 1; i < row.names.size() && i < row.cells.size(); ++i)
            for (size_t c = 1; c < layout.size() && c < again.size(); ++c)
                if (row.names[i] == layout[c] && row.cells[i] != again[c])
                    keep.emplace_back(layout[c], std::string(row.cells[i]));
        if (!keep.empty()) {
            const std::string cells = vendor_csv::encodeCells(keep);
            out.chunk(s.hostTimeNs, reinterpret_cast<const uint8_t *>(cells.data()), cells.size(),
                      ChunkSink::Role::KeptCells);
        }
        const auto frame = hp::buildFrame(hp::encode(h));
        out.chunk(s.hostTimeNs, frame.data(), frame.size());
    });
    r.ok = read.ok;
    r.error = read.error;
    r.rows = read.samples;
    r.badLines = read.badLines;
    for (const auto &e : read.errors)
        r.lineErrors << e.message;
    return r;
}

// --- a raw dump -----------------------------------------------------------------------------

const char *HipnucRawDumpImport::family() const
{
    return HipnucStreamDecoder::kFamily;
}

bool HipnucRawDumpImport::recognises(const QByteArray &head, bool whole) const
{
    Scan scan;
    scan.feed(reinterpret_cast<const uint8_t *>(head.constData()), size_t(head.size()), nullptr);
    if (whole)
        scan.finish(nullptr);
    return scan.frames > 0 || scan.sentences > 0;
}

QString HipnucRawDumpImport::looksLike() const
{
    return tr("a raw dump of what a module sent (HiPNUC frames or NMEA sentences in its first %1 KiB)")
        .arg(kSniffBytes / 1024);
}

FileImporter::Result HipnucRawDumpImport::convert(const QString &path, ChunkSink &out) const
{
    Result r;
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly)) {
        r.error = tr("%1 cannot be read: %2").arg(path, in.errorString());
        return r;
    }
    Scan scan;
    DeviceClock clock;
    std::vector<uint8_t> block(kRawChunkBytes);
    int64_t stampNs = 0;
    for (;;) {
        const qint64 n = in.read(reinterpret_cast<char *>(block.data()), qint64(block.size()));
        if (n < 0) {
            r.error = tr("Reading %1 failed: %2").arg(path, in.errorString());
            return r;
        }
        if (n == 0)
            break;
        scan.feed(block.data(), size_t(n), &clock);
        // The block is stamped with the device time of the last frame it completed.
        stampNs = std::max(stampNs, clock.ns());
        out.chunk(stampNs, block.data(), size_t(n));
        r.bytes += uint64_t(n);
    }
    scan.finish(&clock);
    r.frames = scan.frames;
    r.sentences = scan.sentences;
    r.clockJumps = clock.jumps();
    r.deviceClock = clock.known();
    r.ok = true;
    return r;
}

} // namespace imudesk::decode
