#include "capture_source.h"

#include "protocol/hipnuc/payloads.h"
#include "protocol/nmea/nmea_sample.h"
#include "protocol/stream/stream_demux.h"
#include "capture/capture_format.h"
#include "decode/hipnuc_stream_decoder.h"
#include "record/converted_capture.h"
#include "capture/capture_reader.h"
#include "record/csv_capture_converter.h"
#include "record/vendor_csv_importer.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <algorithm>
#include <vector>

namespace imudesk::record {

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

CaptureSource::CaptureSource() = default;
CaptureSource::~CaptureSource() = default;

const char *CaptureSource::kindName(Kind k)
{
    switch (k) {
    case Kind::Capture: return "capture";
    case Kind::VendorCsv: return "vendor CSV";
    case Kind::RawDump: return "raw byte dump";
    case Kind::Unknown: break;
    }
    return "unknown";
}

CaptureSource::Kind CaptureSource::detect(const QString &path, QString *error)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("%1 cannot be read: %2").arg(path, f.errorString());
        return Kind::Unknown;
    }
    const QByteArray head = f.read(kSniffBytes);
    if (head.isEmpty()) {
        if (error)
            *error = tr("%1 is empty").arg(path);
        return Kind::Unknown;
    }
    if (head.startsWith(QByteArray(capture::kMagic, sizeof capture::kMagic)))
        return Kind::Capture;
    if (head.startsWith("HI91,"))
        return Kind::VendorCsv;
    Scan scan;
    scan.feed(reinterpret_cast<const uint8_t *>(head.constData()), size_t(head.size()), nullptr);
    if (f.atEnd())
        scan.finish(nullptr);
    if (scan.frames > 0 || scan.sentences > 0)
        return Kind::RawDump;
    if (error)
        *error = tr("%1 is neither an ImuDesk capture, a vendor CSV (first line \"HI91,...\") nor a raw dump of what "
                    "a module sent: its first %2 KiB hold no HiPNUC frame and no NMEA sentence")
                     .arg(path)
                     .arg(kSniffBytes / 1024);
    return Kind::Unknown;
}

bool CaptureSource::prepare(const QString &path, QString *error)
{
    m_notes.clear();
    m_temp.reset();
    m_capturePath.clear();
    QString why;
    m_kind = detect(path, &why);
    if (m_kind == Kind::Unknown) {
        if (error)
            *error = why;
        return false;
    }
    if (m_kind == Kind::Capture) {
        m_capturePath = path;
        return true;
    }
    m_temp = std::make_unique<QTemporaryDir>();
    if (!m_temp->isValid()) {
        if (error)
            *error = tr("No temporary folder to convert %1 in: %2").arg(path, m_temp->errorString());
        return false;
    }
    const QString converted = m_temp->filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".imucap"));
    if (m_kind == Kind::VendorCsv) {
        const auto r = CsvCaptureConverter::convert(path, converted);
        if (!r.ok) {
            if (error)
                *error = r.error;
            return false;
        }
        m_notes << tr("%1 is a vendor CSV: %n row(s) read, times from its pc_counter column", nullptr,
                      int(r.import.samples))
                       .arg(QFileInfo(path).fileName());
        for (const auto &e : r.import.errors)
            m_notes << e.message;
    } else {
        const RawResult r = convertRawDump(path, converted);
        if (!r.ok) {
            if (error)
                *error = r.error;
            return false;
        }
        m_notes << (r.deviceClock ? tr("%1 is a raw byte dump without arrival times: the times shown come from the "
                                       "device's own clock")
                                  : tr("%1 is a raw byte dump without arrival times, and nothing in it carries a "
                                       "device time: every time is 0"))
                       .arg(QFileInfo(path).fileName());
        if (r.clockJumps > 0)
            m_notes << tr("The device clock restarted or jumped %n time(s); the times go on across each jump.", nullptr,
                          int(r.clockJumps));
    }
    m_capturePath = converted;
    return true;
}

CaptureSource::RawResult CaptureSource::convertRawDump(const QString &rawPath, const QString &capturePath)
{
    RawResult r;
    QFile in(rawPath);
    if (!in.open(QIODevice::ReadOnly)) {
        r.error = tr("%1 cannot be read: %2").arg(rawPath, in.errorString());
        return r;
    }
    capture::CaptureHeader header;
    header.set(capture::CaptureHeader::kHostTime, "absent");
    // No pause was recorded: like `imudesk-cli decode`, only the end of the file releases held bytes.
    header.set(capture::CaptureHeader::kIdleMarkers, "1");
    ConvertedCapture out;
    if (!out.open(capturePath, rawPath, "raw byte dump", decode::HipnucStreamDecoder::kFamily, header, &r.error))
        return r;
    Scan scan;
    DeviceClock clock;
    std::vector<uint8_t> block(kRawChunkBytes);
    int64_t stampNs = 0;
    for (;;) {
        const qint64 n = in.read(reinterpret_cast<char *>(block.data()), qint64(block.size()));
        if (n < 0) {
            r.error = tr("Reading %1 failed: %2").arg(rawPath, in.errorString());
            out.discard();
            return r;
        }
        if (n == 0)
            break;
        scan.feed(block.data(), size_t(n), &clock);
        // The block is stamped with the device time of the last frame it completed.
        stampNs = std::max(stampNs, clock.ns());
        out.append(stampNs, block.data(), size_t(n));
        r.bytes += uint64_t(n);
    }
    scan.finish(&clock);
    if (!out.finish(&r.error))
        return r;
    r.frames = scan.frames;
    r.sentences = scan.sentences;
    r.clockJumps = clock.jumps();
    r.deviceClock = clock.known();
    r.ok = true;
    return r;
}

} // namespace imudesk::record
