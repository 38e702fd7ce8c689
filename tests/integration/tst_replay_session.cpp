// Record from the simulated module (in this process, sim::SimulatedTransport), replay the capture through
// ReplaySession and compare every decoded value with what the live session decoded from
// the simulator's bytes; then paced playback, seek, loop, pause, a raw dump of the same bytes,
// and a missing file.
#include "../common/capture_bytes.h"
#include "../common/sim_session.h"
#include "../common/synthetic_capture.h"
#include "../common/test_main.h"
#include "device/device_session.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "record/capture_exporter.h"
#include "record/replay_group.h"
#include "record/replay_session.h"
#include "record/recording.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using device::DeviceSession;
using device::SessionState;
using record::ReplaySession;

namespace {

QString differences(const model::Sample &a, const model::Sample &b)
{
    QStringList d;
    auto vec = [&](const char *name, const model::Vec3 &x, const model::Vec3 &y) {
        if (!(x == y))
            d << QLatin1String(name);
    };
    if (a.source != b.source)
        d << QStringLiteral("source");
    if (a.fields != b.fields)
        d << QStringLiteral("fields");
    if (a.mainStatus != b.mainStatus || a.insStatus != b.insStatus)
        d << QStringLiteral("status");
    if (a.deviceTimeMs != b.deviceTimeMs)
        d << QStringLiteral("deviceTime");
    vec("acc", a.acc, b.acc);
    vec("gyr", a.gyr, b.gyr);
    vec("mag", a.mag, b.mag);
    vec("vel", a.velEnu, b.velEnu);
    vec("hss", a.heaveSurgeSway, b.heaveSurgeSway);
    if (a.roll != b.roll || a.pitch != b.pitch || a.yaw != b.yaw)
        d << QStringLiteral("euler");
    if (!(a.quat == b.quat))
        d << QStringLiteral("quat");
    if (a.pressurePa != b.pressurePa || a.temperatureC != b.temperatureC)
        d << QStringLiteral("pressure/temperature");
    if (a.latitudeDeg != b.latitudeDeg || a.longitudeDeg != b.longitudeDeg || a.altitudeM != b.altitudeM)
        d << QStringLiteral("position");
    if (a.inclinationX != b.inclinationX || a.inclinationY != b.inclinationY)
        d << QStringLiteral("inclination");
    return d.join(QLatin1Char(','));
}

// The live samples of the frames a capture holds. The capture is a stretch of the byte stream
// the live session decoded; the engine starts and stops recording between two reads, at a
// moment the test thread cannot see, so `live` (all samples from just before the start to
// just after the stop) may have a few more at either end. The capture's first and last HI91
// frames (device clock) place it in `live`; one sample per frame here. Empty if they are not
// found in `live`.
std::vector<model::Sample> recordedStretch(const std::vector<model::Sample> &live, const QByteArray &captured)
{
    protocol::hipnuc::FrameDecoder decoder;
    const auto frames = decoder.feed(reinterpret_cast<const uint8_t *>(captured.constData()), size_t(captured.size()));
    std::vector<std::pair<size_t, double>> hi91; // frame index, device time (ms)
    for (size_t i = 0; i < frames.size(); ++i) {
        protocol::hipnuc::Hi91 h;
        if (protocol::hipnuc::decodeHi91(frames[i].data(), frames[i].size(), h))
            hi91.emplace_back(i, double(h.systemTime));
    }
    if (hi91.empty())
        return {};
    const auto find = [&live](double timeMs, size_t from) {
        for (size_t j = from; j < live.size(); ++j)
            if (live[j].source == "HI91" && live[j].deviceTimeMs == timeMs)
                return j;
        return live.size();
    };
    const size_t first = find(hi91.front().second, 0);
    if (first == live.size() || first < hi91.front().first)
        return {};
    const size_t last = find(hi91.back().second, first);
    const size_t begin = first - hi91.front().first;
    const size_t end = last + (frames.size() - hi91.back().first); // one past the capture's last frame
    if (last == live.size() || end > live.size())
        return {};
    return std::vector<model::Sample>(live.begin() + qsizetype(begin), live.begin() + qsizetype(end));
}

} // namespace

class TstReplaySession : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_capture;
    std::vector<model::Sample> m_live;
    double m_duration = 0;
    uint64_t m_recordedFrames = 0;

    std::vector<model::Sample> playAll(ReplaySession &replay)
    {
        QSignalSpy finished(&replay, &ReplaySession::finished);
        const uint64_t from = replay.store().totalAppended();
        replay.setSpeed(ReplaySession::kAsFastAsPossible);
        replay.play();
        if (!finished.wait(20000))
            return {};
        return replay.store().since(from);
    }

private Q_SLOTS:
    void initTestCase()
    {
        sim::SimOptions o;
        o.baud = 921600;
        o.motion = sim::Motion::Tumble;
        o.seed = 5;
        test::SimSession sim(o);
        DeviceSession &session = sim.session;
        QSignalSpy identity(&session, &DeviceSession::identityChanged);
        sim.open(921600);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Connected, 10000);
        QVERIFY(!identity.isEmpty() || identity.wait(5000));
        // HI91 at 200 Hz and HI81 at 20 Hz share the line.
        QSignalSpy done(&session, &DeviceSession::commandFinished);
        session.sendText(QStringLiteral("LOG HI91 ONTIME 0.005"));
        session.sendText(QStringLiteral("LOG HI81 ONTIME 0.05"));
        QTRY_COMPARE_WITH_TIMEOUT(done.size(), 2, 5000);
        const uint64_t configured = session.store().totalAppended();
        const auto hi81Arrived = [&session, configured] {
            for (const auto &sample : session.store().since(configured))
                if (sample.source == "HI81")
                    return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(hi81Arrived(), 5000); // both streams run

        m_capture = m_dir.filePath(QStringLiteral("sim.imucap"));
        QSignalSpy started(&session, &DeviceSession::recordingStarted);
        QSignalSpy stopped(&session, &DeviceSession::recordingStopped);
        QSignalSpy progress(&session, &DeviceSession::recordingProgress);
        const uint64_t before = session.store().totalAppended();
        record::startRecording(session, m_capture);
        QVERIFY(started.wait(5000));
        QTest::qWait(2000); // duration under test: two seconds recorded (the replay's duration is checked)
        session.stopRecording();
        QVERIFY(stopped.wait(5000));
        QCOMPARE(stopped.at(0).at(0).toString(), QString()); // stopped as asked
        QVERIFY(!progress.isEmpty());
        m_recordedFrames = progress.last().at(1).toULongLong(); // frames decoded from the recorded bytes
        const auto live = session.store().since(before);
        session.close();
        m_live = recordedStretch(live, test::receivedBytes(m_capture));
        qInfo("%zu live samples from the start to the stop, %zu of them in the capture", live.size(), m_live.size());
        QVERIFY(m_live.size() > 100); // 2 s at 220 frames/s, fewer when the machine starves the simulator
    }

    void replayDecodesWhatTheLiveSessionDecoded()
    {
        ReplaySession replay;
        QSignalSpy opened(&replay, &ReplaySession::opened);
        QSignalSpy identity(&replay, &ReplaySession::identityChanged);
        replay.open(m_capture);
        QVERIFY(opened.wait(5000));
        QCOMPARE(replay.state(), SessionState::Connected);
        m_duration = opened.at(0).at(0).toDouble();
        QVERIFY(m_duration > 1.8 && m_duration < 2.5);
        const auto header = opened.at(0).at(1).value<capture::CaptureHeader>();
        QCOMPARE(header.baud(), 921600);
        QCOMPARE(header.value(capture::CaptureHeader::kLinkKind), std::string("HiPNUC serial"));
        QCOMPARE(identity.size(), 1);
        QCOMPARE(identity.at(0).at(0).value<model::DeviceIdentity>().productName, std::string("HI14R3"));

        const auto replayed = playAll(replay);
        QVERIFY(replayed.size() > 100);
        // The recording began while the stream ran: find the first replayed sample live.
        size_t offset = 0;
        while (offset < m_live.size() && !differences(m_live[offset], replayed.front()).isEmpty())
            ++offset;
        QVERIFY2(offset < m_live.size(), "the first replayed sample was never decoded live");
        size_t hi81 = 0;
        for (size_t i = 0; i < replayed.size(); ++i) {
            QVERIFY2(offset + i < m_live.size(), "replay decoded more samples than the live session");
            const QString diff = differences(m_live[offset + i], replayed[i]);
            QVERIFY2(diff.isEmpty(), qPrintable(QStringLiteral("sample %1 differs in %2").arg(i).arg(diff)));
            hi81 += replayed[i].source == "HI81";
        }
        // The recording counts the frames the file holds (one begun before it started is not
        // counted), and every one of them is replayed (one sample per frame here).
        QVERIFY2(replayed.size() == m_recordedFrames,
                 qPrintable(QStringLiteral("%1 replayed, %2 recorded").arg(replayed.size()).arg(m_recordedFrames)));
        QVERIFY(hi81 > 5);
    }

    void pacedPlaybackFollowsSpeed_data()
    {
        QTest::addColumn<double>("speed");
        QTest::newRow("2x") << 2.0;
        QTest::newRow("10x") << 10.0;
    }
    void pacedPlaybackFollowsSpeed()
    {
        QFETCH(double, speed);
        ReplaySession replay;
        QSignalSpy opened(&replay, &ReplaySession::opened);
        replay.open(m_capture);
        QVERIFY(opened.wait(5000));
        const double duration = opened.at(0).at(0).toDouble();
        QSignalSpy finished(&replay, &ReplaySession::finished);
        QSignalSpy position(&replay, &ReplaySession::positionChanged);
        replay.setSpeed(speed);
        QElapsedTimer t;
        t.start();
        replay.play();
        QVERIFY(finished.wait(20000));
        const double took = double(t.elapsed()) / 1000.0;
        // Never faster than the speed asked; slower only by what a loaded machine costs.
        QVERIFY2(took > duration / speed * 0.9 && took < duration / speed * 2.0 + 0.5,
                 qPrintable(QStringLiteral("took %1 s for %2 s at %3x").arg(took).arg(duration).arg(speed)));
        QVERIFY(position.size() >= 2);
        QCOMPARE(position.last().at(0).toDouble(), duration);
    }

    void seekPlaysFromThere()
    {
        ReplaySession replay;
        QSignalSpy opened(&replay, &ReplaySession::opened);
        replay.open(m_capture);
        QVERIFY(opened.wait(5000));
        const double duration = opened.at(0).at(0).toDouble();
        const auto all = playAll(replay);
        QSignalSpy position(&replay, &ReplaySession::positionChanged);
        replay.seek(duration / 2);
        QVERIFY(position.wait(2000));
        QVERIFY(qAbs(position.last().at(0).toDouble() - duration / 2) < 1e-6);
        const auto half = playAll(replay);
        QVERIFY2(half.size() > all.size() * 4 / 10 && half.size() < all.size() * 6 / 10,
                 qPrintable(QStringLiteral("%1 of %2").arg(half.size()).arg(all.size())));
        // The second half is the tail of the whole replay.
        QVERIFY(differences(half.back(), all.back()).isEmpty());
        QVERIFY(differences(half[half.size() / 2], all[all.size() - half.size() + half.size() / 2]).isEmpty());
    }

    void loopsAndPauses()
    {
        ReplaySession replay;
        QSignalSpy opened(&replay, &ReplaySession::opened);
        replay.open(m_capture);
        QVERIFY(opened.wait(5000));
        const auto all = playAll(replay);
        const uint64_t once = all.size();
        replay.seek(0);
        replay.setLoop(true);
        QSignalSpy playing(&replay, &ReplaySession::playingChanged);
        replay.play();
        QTRY_VERIFY_WITH_TIMEOUT(replay.store().totalAppended() > 3 * once, 20000);
        replay.pause();
        QTRY_VERIFY(!playing.isEmpty() && !playing.last().at(0).toBool());
        const uint64_t paused = replay.store().totalAppended();
        QTest::qWait(100); // duration under test: nothing is replayed for 100 ms while paused
        QCOMPARE(replay.store().totalAppended(), paused);
    }

    void rawDumpReplaysWithTheDeviceClock()
    {
        // The recording's bytes alone (a terminal's log): opened by content, every sample the
        // capture gave, a duration from the device clock, and the header says the host times are absent.
        const QByteArray raw = test::receivedBytes(m_capture);
        QVERIFY(!raw.isEmpty());
        const QString dump = m_dir.filePath(QStringLiteral("putty.log"));
        QFile f(dump);
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write(raw) == raw.size());
        f.close();
        ReplaySession replay;
        QSignalSpy opened(&replay, &ReplaySession::opened);
        QSignalSpy finished(&replay, &ReplaySession::finished);
        replay.open(dump);
        QVERIFY(opened.wait(10000));
        const auto header = opened.at(0).at(1).value<capture::CaptureHeader>();
        QCOMPARE(header.value(capture::CaptureHeader::kHostTime), std::string("absent"));
        const double duration = opened.at(0).at(0).toDouble();
        QVERIFY2(duration > 1.5 && duration < 2.5, qPrintable(QString::number(duration))); // 2 s of device time
        replay.setSpeed(0);
        replay.play();
        QVERIFY(finished.wait(10000));
        // The same samples as the export of the dump (one decoding path), and as the live session
        // but for at most one frame at an edge of the recording: the live session and the capture
        // had the line's context around it (bytes held when recording began, idle markers), a
        // dump only has its bytes.
        record::CaptureExporter::Options eo;
        eo.format = record::CaptureExporter::Format::JsonLines;
        eo.output = m_dir.filePath(QStringLiteral("putty.jsonl"));
        const auto exported = record::CaptureExporter::run(dump, eo);
        QVERIFY2(exported.ok, qPrintable(exported.error));
        QCOMPARE(replay.store().totalAppended(), exported.frames);
        QVERIFY2(replay.store().totalAppended() + 1 >= m_live.size() && replay.store().totalAppended() <= m_live.size(),
                 qPrintable(QStringLiteral("%1 of %2").arg(replay.store().totalAppended()).arg(m_live.size())));
    }

    // A recorded session's devices (replay_group.h): each capture on the session's timeline, so
    // one position is one instant in all of them; play, pause, seek and speed asked of one
    // member act on all; the device's twist-to-align offset lands on its common times.
    void sessionMembersShareTheTimeline()
    {
        synthetic::CaptureSpec a, b;
        a.frames = 2000; // 5.0 .. 7.0 s on the host clock
        b.frames = 1000;
        b.rateHz = 500;
        b.seed = 2;
        b.t0Ns = 6'000'000'000; // 6.0 .. 8.0 s: started later
        const QString pa = m_dir.filePath(QStringLiteral("a.imucap")), pb = m_dir.filePath(QStringLiteral("b.imucap"));
        QVERIFY(synthetic::writeCapture(pa, a) > 0 && synthetic::writeCapture(pb, b) > 0);
        // B alone, as a capture of its own: the reference for its offset.
        ReplaySession alone;
        QSignalSpy aloneOpened(&alone, &ReplaySession::opened);
        alone.open(pb);
        QVERIFY(aloneOpened.wait(5000));
        QVERIFY(qAbs(aloneOpened.at(0).at(0).toDouble() - 1.984) < 1e-6); // its first chunk (8 frames in) to its last
        QCOMPARE(playAll(alone).size(), size_t(1000));
        alone.setSpeed(ReplaySession::kAsFastAsPossible);

        auto group = std::make_shared<record::ReplayGroup>();
        record::ReplayTimeline t{4'500'000'000, 8'500'000'000, 0};
        auto ra = std::make_unique<ReplaySession>(), rb = std::make_unique<ReplaySession>();
        ra->setGroup(group);
        rb->setGroup(group);
        QCOMPARE(int(group->members().size()), 2);
        QSignalSpy openedA(ra.get(), &ReplaySession::opened), openedB(rb.get(), &ReplaySession::opened);
        ra->open(pa, t);
        t.offsetNs = 1'500'000; // B's clock 1.5 ms behind A's: twist to align found it
        rb->open(pb, t);
        QVERIFY(openedA.wait(5000) && (!openedB.isEmpty() || openedB.wait(5000)));
        QCOMPARE(openedA.at(0).at(0).toDouble(), 4.0); // the session's start to its stop
        QCOMPARE(openedB.at(0).at(0).toDouble(), 4.0);

        // Seek one: both go to 2.0 s into the session (6.5 s on the host clock).
        QSignalSpy posA(ra.get(), &ReplaySession::positionChanged), posB(rb.get(), &ReplaySession::positionChanged);
        rb->seek(2.0);
        // Waited for as the last position each reports: a position B's opening still had on its way
        // (0 s) may come in before the seek's (seen once under AddressSanitizer).
        auto lastOf = [](const QSignalSpy &spy) { return spy.isEmpty() ? -1.0 : spy.last().at(0).toDouble(); };
        QTRY_COMPARE(lastOf(posA), 2.0);
        QTRY_COMPARE(lastOf(posB), 2.0);
        // Play one at 10x: both play; pause the other: both pause.
        QSignalSpy playingA(ra.get(), &ReplaySession::playingChanged), playingB(rb.get(), &ReplaySession::playingChanged);
        const uint64_t fromA = ra->store().totalAppended(), fromB = rb->store().totalAppended();
        rb->setSpeed(10.0);
        ra->play();
        QTRY_VERIFY(!playingA.isEmpty() && !playingB.isEmpty());
        QVERIFY(playingA.last().at(0).toBool() && playingB.last().at(0).toBool());
        QTRY_VERIFY_WITH_TIMEOUT(ra->store().totalAppended() > fromA + 100 && rb->store().totalAppended() > fromB + 50, 5000);
        rb->pause();
        QTRY_VERIFY(!playingA.last().at(0).toBool() && !playingB.last().at(0).toBool());
        const auto sa = ra->store().since(fromA), sb = rb->store().since(fromB);
        // The first samples after the seek are the ones at 6.5 s in both captures.
        QVERIFY(sa.front().hostTimeNs >= 6'500'000'000 && sa.front().hostTimeNs < 6'510'000'000);
        QVERIFY(sb.front().hostTimeNs >= 6'500'000'000 && sb.front().hostTimeNs <= 6'516'000'000); // its chunks: 16 ms
        // Paused together: at 10x their positions agree within a few ticks (5 ms of wall time is
        // 50 ms of the session), once each one's report from its pause is in (it follows its
        // playingChanged).
        QTRY_VERIFY2(qAbs(posA.last().at(0).toDouble() - posB.last().at(0).toDouble()) < 0.25,
                     qPrintable(QStringLiteral("%1 / %2").arg(posA.last().at(0).toDouble()).arg(posB.last().at(0).toDouble())));
        // B's common times are the capture's own plus the offset, sample for sample (B alone,
        // played from the same instant: 6.5 s on the host clock, 0.484 s after its first chunk).
        const uint64_t fromAlone = alone.store().totalAppended();
        alone.seek(0.484);
        const auto reference = [&] {
            QSignalSpy finished(&alone, &ReplaySession::finished);
            alone.play();
            finished.wait(20000);
            return alone.store().since(fromAlone);
        }();
        size_t k = 0;
        while (k < reference.size() && reference[k].hostTimeNs != sb.front().hostTimeNs)
            ++k;
        QVERIFY(k + sb.size() <= reference.size());
        for (size_t i = 0; i < sb.size(); ++i) {
            const model::Sample &r = reference[k + i];
            QCOMPARE(sb[i].hostTimeNs, r.hostTimeNs);
            QCOMPARE(sb[i].commonTimeNs, (r.commonTimeNs != 0 ? r.commonTimeNs : r.hostTimeNs) + 1'500'000);
        }
        // A member that goes leaves the group; the other plays on its own.
        ra.reset();
        QCOMPARE(int(group->members().size()), 1);
        QSignalSpy finishedB(rb.get(), &ReplaySession::finished);
        rb->play();
        QVERIFY(finishedB.wait(5000));
    }

    // A capture of a family ImuDesk has no decoder for is refused with its name, not played
    // as a HiPNUC stream that decodes as nothing (its bytes here are HiPNUC frames: decoded as
    // HiPNUC they would play).
    void aFamilyWithoutADecoderIsRefused()
    {
        synthetic::CaptureSpec spec;
        spec.frames = 200;
        spec.linkKind = "Xsens MTi serial";
        const QString path = m_dir.filePath(QStringLiteral("xsens.imucap"));
        QVERIFY(synthetic::writeCapture(path, spec) > 0);
        ReplaySession replay;
        QSignalSpy error(&replay, &ReplaySession::errorOccurred);
        replay.open(path);
        QVERIFY(error.wait(5000));
        QCOMPARE(replay.state(), SessionState::Failed);
        const QString why = error.at(0).at(0).toString();
        QVERIFY2(why.contains(QStringLiteral("xsens.imucap")) && why.contains(QStringLiteral("\"Xsens MTi serial\" link")),
                 qPrintable(why));
        QCOMPARE(replay.store().totalAppended(), uint64_t(0));
    }

    void missingFileFails()
    {
        ReplaySession replay;
        QSignalSpy error(&replay, &ReplaySession::errorOccurred);
        replay.open(m_dir.filePath(QStringLiteral("nope.imucap")));
        QVERIFY(error.wait(5000));
        QCOMPARE(replay.state(), SessionState::Failed);
        QVERIFY(error.at(0).at(0).toString().contains(QStringLiteral("nope.imucap")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstReplaySession)
#include "tst_replay_session.moc"
