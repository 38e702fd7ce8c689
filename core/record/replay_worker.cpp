#include "replay_worker.h"

#include "model/main_status.h"

#include "device/stream_counters.h"

#include <QFileInfo>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace imudesk::record {

namespace {
constexpr int kPacedTickMs = 5;
constexpr qint64 kMaxBusyMs = 20;          // as fast as possible: yield to the event loop this often
constexpr int64_t kIndexStepNs = 50'000'000; // one index entry per 50 ms of capture
constexpr int kStatsPeriodMs = 500;
constexpr qint64 kPositionPeriodMs = 100;
} // namespace

ReplayWorker::ReplayWorker(device::SampleStore &store, QObject *parent) : QObject(parent), m_store(store)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &ReplayWorker::tick);
    m_statsTimer.setInterval(kStatsPeriodMs);
    connect(&m_statsTimer, &QTimer::timeout, this, &ReplayWorker::publishStats);
}

ReplayWorker::~ReplayWorker() = default;

void ReplayWorker::open(const QString &path, const ReplayTimeline &timeline)
{
    close();
    m_timeline = timeline;
    Q_EMIT stateChanged(device::SessionState::Opening, path);
    QString error;
    // A capture, or a vendor CSV or raw byte dump converted to one (recognised by content).
    if (!m_source.prepare(path, &error) || !m_reader.open(m_source.capturePath(), &error)) {
        Q_EMIT stateChanged(device::SessionState::Failed, error);
        Q_EMIT errorOccurred(error);
        return;
    }
    // The decoder of the family the capture names; a family without one is refused by name.
    m_decoder.setNmeaSamples(true); // positions and fixes in the values, as live
    if (!m_decoder.configure(m_reader.header())) {
        error = tr("%1: %2").arg(QFileInfo(path).fileName(), m_decoder.error());
        m_reader.close();
        Q_EMIT stateChanged(device::SessionState::Failed, error);
        Q_EMIT errorOccurred(error);
        return;
    }
    // Index the timeline (one entry per kIndexStepNs) so that seeking reads little.
    m_index.clear();
    capture::CaptureReader::Chunk c;
    capture::CaptureReader::Result r;
    bool first = true;
    int64_t lastNs = 0;
    while ((r = m_reader.next(c)) == capture::CaptureReader::Result::Chunk || r == capture::CaptureReader::Result::Damaged) {
        if (r != capture::CaptureReader::Result::Chunk)
            continue;
        if (first) {
            // A session's capture counts from the session's start, as every other device's does
            // (a chunk from before it plays at once).
            m_firstNs = m_timeline.originNs != 0 ? m_timeline.originNs : c.monotonicNs;
            first = false;
        }
        const int64_t rel = c.monotonicNs - m_firstNs;
        if (m_index.empty() || rel - m_index.back().relNs >= kIndexStepNs)
            m_index.push_back({c.offset, rel});
        lastNs = std::max(lastNs, rel);
    }
    if (r == capture::CaptureReader::Result::Truncated || m_reader.damagedChunks() > 0)
        Q_EMIT errorOccurred(tr("%1: %2. Replaying what is intact.")
                                 .arg(QFileInfo(path).fileName(),
                                      m_reader.damagedChunks() > 0
                                          ? tr("%n damaged chunk(s) skipped", nullptr, int(m_reader.damagedChunks()))
                                          : m_reader.message()));
    m_durationNs = std::max(lastNs, m_timeline.endNs > m_firstNs ? m_timeline.endNs - m_firstNs : int64_t(0));
    m_reader.seek(m_reader.dataStart());
    m_gaps.clear(); // the decoder configured above is fresh: indexing fed it nothing
    m_posNs = 0;
    m_drained = false;
    m_open = true;
    m_baud = m_reader.header().baud();
    m_lastStats = device::SessionStats{};
    m_statsClock.start();
    m_lastStatsMs = 0;
    m_statsTimer.start();
    m_positionClock.start();
    Q_EMIT stateChanged(device::SessionState::Connected, path);
    Q_EMIT identityChanged(m_reader.header().identity());
    Q_EMIT opened(double(m_durationNs) / 1e9, m_reader.header());
    reportPosition(true);
}

void ReplayWorker::close()
{
    m_timer.stop();
    m_statsTimer.stop();
    setPlaying(false);
    if (!m_open)
        return;
    publishStats();
    m_reader.close();
    m_open = false;
    Q_EMIT stateChanged(device::SessionState::Closed, QString());
}

void ReplayWorker::setPlaying(bool on)
{
    if (m_playing == on)
        return;
    m_playing = on;
    Q_EMIT playingChanged(on);
}

void ReplayWorker::anchor()
{
    m_anchorNs = m_posNs;
    m_wall.restart();
}

void ReplayWorker::play()
{
    if (!m_open)
        return;
    if (m_posNs >= m_durationNs && !m_loop)
        seekTo(0); // play again from the start
    anchor();
    setPlaying(true);
    m_timer.start(m_speed > 0 ? kPacedTickMs : 0);
}

void ReplayWorker::pause()
{
    m_timer.stop();
    setPlaying(false);
    reportPosition(true);
}

void ReplayWorker::setSpeed(double factor)
{
    m_speed = factor;
    anchor();
    if (m_playing)
        m_timer.start(m_speed > 0 ? kPacedTickMs : 0);
}

void ReplayWorker::setLoop(bool on)
{
    m_loop = on;
}

void ReplayWorker::seek(double seconds)
{
    if (!m_open)
        return;
    seekTo(std::clamp(int64_t(seconds * 1e9), int64_t(0), m_durationNs));
    anchor();
    reportPosition(true);
}

void ReplayWorker::seekTo(int64_t relNs)
{
    auto it = std::upper_bound(m_index.begin(), m_index.end(), relNs,
                               [](int64_t t, const IndexEntry &e) { return t < e.relNs; });
    m_reader.seek(it == m_index.begin() ? m_reader.dataStart() : std::prev(it)->offset);
    m_decoder.reset();
    m_gaps.resetTiming();
    capture::CaptureReader::Chunk c;
    capture::CaptureReader::Result r;
    while ((r = m_reader.next(c)) == capture::CaptureReader::Result::Chunk || r == capture::CaptureReader::Result::Damaged) {
        if (r == capture::CaptureReader::Result::Chunk && c.monotonicNs - m_firstNs >= relNs) {
            m_reader.seek(c.offset);
            break;
        }
    }
    m_posNs = relNs;
    m_drained = false;
}

void ReplayWorker::tick()
{
    if (!m_playing || !m_open)
        return;
    QElapsedTimer busy;
    busy.start();
    const int64_t target = m_speed > 0 ? m_anchorNs + int64_t(double(m_wall.nsecsElapsed()) * m_speed)
                                       : std::numeric_limits<int64_t>::max();
    capture::CaptureReader::Chunk c;
    bool atEnd = false;
    for (;;) {
        if (m_speed <= 0 && busy.elapsed() >= kMaxBusyMs)
            break;
        const capture::CaptureReader::Result r = m_reader.next(c);
        if (r == capture::CaptureReader::Result::Damaged)
            continue;
        if (r != capture::CaptureReader::Result::Chunk) {
            atEnd = true;
            break;
        }
        const int64_t rel = c.monotonicNs - m_firstNs;
        if (rel > target) {
            m_reader.seek(c.offset);
            break;
        }
        m_decoder.feedChunk(c, *this);
        m_posNs = std::max(m_posNs, rel);
    }
    if (atEnd) {
        if (!m_drained) {
            m_decoder.finish(*this);
            m_drained = true;
        }
        if (m_speed > 0 && target < m_durationNs) {
            // A device of a session whose data ends before the session does (it dropped out, or
            // stopped first): its timeline goes on with the others'.
            m_posNs = std::max(m_posNs, target);
            flushBatch();
            reportPosition(false);
            return;
        }
        m_posNs = m_durationNs;
    } else if (m_speed > 0) {
        m_posNs = std::clamp(target, m_posNs, m_durationNs);
    }
    flushBatch();
    reportPosition(atEnd);
    if (!atEnd)
        return;
    if (m_loop) {
        seekTo(0);
        anchor();
        return;
    }
    m_timer.stop();
    setPlaying(false);
    publishStats();
    Q_EMIT finished();
}

void ReplayWorker::onSample(const model::Sample &sample, const decode::Record &)
{
    m_batch.push_back(sample); // its arrival and common time as the live session had them
    model::Sample &s = m_batch.back();
    applyOffset(s);
    if (s.has(model::FieldDeviceTime))
        m_gaps.add(s.source, s.deviceTimeMs, model::MainStatus::timeBase(s.has(model::FieldMainStatus), s.mainStatus));
}

void ReplayWorker::applyOffset(model::Sample &s) const
{
    // Twist to align: the device's constant offset, on its common time (its arrival where it
    // has none), as the session's export places it.
    if (m_timeline.offsetNs != 0)
        s.commonTimeNs = (s.commonTimeNs != 0 ? s.commonTimeNs : s.hostTimeNs) + m_timeline.offsetNs;
}

void ReplayWorker::onText(decode::TextKind kind, const std::string &text, int64_t)
{
    if (kind != decode::TextKind::Line)
        Q_EMIT nmeaReceived(QString::fromStdString(text));
}

void ReplayWorker::flushBatch()
{
    if (m_batch.empty())
        return;
    m_store.append(m_batch);
    m_batch.clear();
}

void ReplayWorker::reportPosition(bool force)
{
    const qint64 now = m_positionClock.isValid() ? m_positionClock.elapsed() : 0;
    if (!force && now - m_lastPositionMs < kPositionPeriodMs)
        return;
    m_lastPositionMs = now;
    Q_EMIT positionChanged(double(m_posNs) / 1e9);
}

void ReplayWorker::publishStats()
{
    device::SessionStats s;
    device::addDecodeCounters(m_decoder.counters(), s); // the family's decoder's, as live
    device::addGapCounters(m_gaps, s);
    s.baud = m_baud;
    const qint64 nowMs = m_statsClock.isValid() ? m_statsClock.elapsed() : 0;
    const double dt = double(nowMs - m_lastStatsMs) / 1000.0;
    if (device::addRates(s, m_lastStats, dt)) {
        m_lastStats = s;
        m_lastStatsMs = nowMs;
    }
    Q_EMIT statsUpdated(s);
}

} // namespace imudesk::record
