// ReplayControls offscreen on a ReplaySession of a generated capture: play/pause, speed,
// seeking on the timeline, loop, and the position label.
#include "../common/synthetic_capture.h"
#include "../common/test_main.h"
#include "record/replay_session.h"
#include "recording/replay_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using ui::ReplayControls;

class TstReplayControls : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_capture;

private Q_SLOTS:
    void initTestCase()
    {
        m_capture = m_dir.filePath(QStringLiteral("three_seconds.imucap"));
        synthetic::CaptureSpec spec;
        spec.frames = 3000;
        QVERIFY(synthetic::writeCapture(m_capture, spec) > 0);
    }

    void playPauseSpeedSeekLoop()
    {
        record::ReplaySession replay;
        ReplayControls c;
        c.setSession(&replay);
        QSignalSpy opened(&replay, &record::ReplaySession::opened);
        replay.open(m_capture);
        QVERIFY(opened.wait(5000));
        QVERIFY(std::abs(c.duration() - 2.992) < 0.01);
        auto *play = c.findChild<QPushButton *>(QStringLiteral("play"));
        auto *speed = c.findChild<QComboBox *>(QStringLiteral("speed"));
        auto *timeline = c.findChild<QSlider *>(QStringLiteral("timeline"));
        auto *loop = c.findChild<QCheckBox *>(QStringLiteral("loop"));
        auto *time = c.findChild<QLabel *>(QStringLiteral("time"));
        QCOMPARE(timeline->maximum(), 2992);
        QCOMPARE(speed->currentData().toDouble(), 1.0);
        QVERIFY(time->text().endsWith(QStringLiteral("00:02.9")));

        // Play at 1x: the position moves with time; pause stops it.
        QSignalSpy playing(&replay, &record::ReplaySession::playingChanged);
        QTest::mouseClick(play, Qt::LeftButton);
        QVERIFY(playing.wait(2000));
        QCOMPARE(play->text(), QStringLiteral("Pause"));
        QTRY_VERIFY_WITH_TIMEOUT(c.position() > 0.3, 3000);
        QTest::mouseClick(play, Qt::LeftButton);
        QTRY_COMPARE(play->text(), QStringLiteral("Play"));
        const uint64_t paused = replay.store().totalAppended();
        QVERIFY(paused > 200);

        // Seek with the timeline: a click on the track (PageStep) seeks at once.
        timeline->setValue(2000);
        timeline->triggerAction(QAbstractSlider::SliderPageStepAdd);
        QTRY_VERIFY(c.position() >= 2.0);

        // As fast as possible to the end.
        QSignalSpy finished(&replay, &record::ReplaySession::finished);
        speed->setCurrentIndex(speed->count() - 1);
        QCOMPARE(speed->currentData().toDouble(), 0.0);
        QTest::mouseClick(play, Qt::LeftButton);
        QVERIFY(finished.wait(5000));
        QCOMPARE(timeline->value(), 2992);
        const uint64_t afterEnd = replay.store().totalAppended();
        QVERIFY(afterEnd - paused < 1100); // only the last second or so was played after the seek

        // Loop: plays the capture again and again until paused.
        loop->setChecked(true);
        QTest::mouseClick(play, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(replay.store().totalAppended() > afterEnd + 7000, 10000);
        QTest::mouseClick(play, Qt::LeftButton);
        QTRY_COMPARE(play->text(), QStringLiteral("Play"));
    }

    void withoutSessionDisabled()
    {
        ReplayControls c;
        QVERIFY(!c.isEnabled());
        auto replay = std::make_unique<record::ReplaySession>();
        c.setSession(replay.get());
        QVERIFY(c.isEnabled());
        replay.reset();
        QVERIFY(!c.isEnabled());
    }
};

IMUDESK_TEST_MAIN(TstReplayControls)
#include "tst_replay_controls.moc"
