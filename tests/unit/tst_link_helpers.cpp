// The engine's two small link helpers on their own: BaudScan (core/device/baud_scan.h), the
// rate search both serial families use, and Reconnector (core/device/reconnector.h), the
// wait for a device that went away. The families and the engine that use them are tested
// end to end in tst_session_engine, tst_device_session and tst_hec495_session.
#include "device/baud_scan.h"
#include "device/reconnector.h"
#include "../common/test_main.h"

#include <QElapsedTimer>
#include <QTest>

#include <map>
#include <vector>

using namespace imudesk;
using device::BaudScan;
using Outcome = BaudScan::Outcome;

namespace {

// A link that can be reopened only from the n-th attempt on.
class FlakyTransport : public io::Transport {
public:
    int attemptsUntilBack = 3;
    int attempts = 0;
    int reopenedAt = 0;
    bool open(const QString &, int, QString *) override { return true; }
    void close() override {}
    bool isOpen() const override { return reopenedAt > 0; }
    bool setBaud(int) override { return true; }
    int baud() const override { return reopenedAt; }
    QString address() const override { return QStringLiteral("flaky"); }
    qint64 write(const QByteArray &b) override { return b.size(); }
    void clear() override {}
    bool reopen(int baud, QString *error) override
    {
        if (++attempts < attemptsUntilBack) {
            *error = QStringLiteral("permission denied");
            return false;
        }
        reopenedAt = baud;
        return true;
    }
};

} // namespace

class TstLinkHelpers : public QObject {
    Q_OBJECT

    // A scan whose probe answers from `answers` (TryNext where none is given), later or at once.
    struct Run {
        std::vector<int> tuned;
        std::vector<int> probed;
        int found = 0;
        bool exhausted = false;
        bool stopped = false;
    };
    static BaudScan::Plan plan(Run &run, std::vector<int> bauds, std::map<int, Outcome> answers, int listenMs,
                               bool deferred)
    {
        BaudScan::Plan p;
        p.bauds = std::move(bauds);
        p.listenMs = listenMs;
        p.tune = [&run](int baud) { run.tuned.push_back(baud); };
        p.probe = [&run, answers, deferred](int baud, BaudScan::Answer answer) {
            run.probed.push_back(baud);
            const auto it = answers.find(baud);
            const Outcome o = it == answers.end() ? Outcome::TryNext : it->second;
            if (deferred)
                QTimer::singleShot(1, [answer, o] { answer(o); });
            else
                answer(o);
        };
        p.found = [&run](int baud) { run.found = baud; };
        p.exhausted = [&run] { run.exhausted = true; };
        p.stopped = [&run] { run.stopped = true; };
        return p;
    }

private Q_SLOTS:
    void scanTriesRatesInOrderUntilFound_data()
    {
        QTest::addColumn<bool>("deferred");
        QTest::newRow("answer later") << true;
        QTest::newRow("answer at once") << false;
    }
    void scanTriesRatesInOrderUntilFound()
    {
        QFETCH(bool, deferred);
        BaudScan scan;
        Run run;
        scan.start(plan(run, {115200, 921600, 9600, 4800}, {{9600, Outcome::Found}}, 0, deferred));
        QTRY_VERIFY(!scan.running());
        QCOMPARE(run.tuned, (std::vector<int>{115200, 921600, 9600}));
        QCOMPARE(run.probed, run.tuned); // 4800 is never tried
        QCOMPARE(run.found, 9600);
        QVERIFY(!run.exhausted);
        QVERIFY(!run.stopped);
    }

    void scanListensBeforeEachProbe()
    {
        BaudScan scan;
        Run run;
        QElapsedTimer clock;
        clock.start();
        scan.start(plan(run, {1, 2, 3}, {}, 60, false));
        QCOMPARE(run.tuned, std::vector<int>{1}); // tuned at once ...
        QVERIFY(run.probed.empty());             // ... asked only after listening
        QTRY_VERIFY(run.exhausted);
        QVERIFY2(clock.elapsed() >= 3 * 60, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(run.probed, (std::vector<int>{1, 2, 3}));
        QCOMPARE(run.found, 0);
    }

    void scanStopOutcomeEndsWithoutVerdict()
    {
        BaudScan scan;
        Run run;
        scan.start(plan(run, {1, 2, 3}, {{2, Outcome::Stop}}, 0, true));
        QTRY_VERIFY(run.stopped);
        QCOMPARE(run.probed, (std::vector<int>{1, 2}));
        QVERIFY(!run.exhausted);
        QVERIFY(!scan.running());
    }

    void staleAnswersAreIgnored()
    {
        BaudScan scan;
        Run run;
        BaudScan::Answer kept;
        BaudScan::Plan p = plan(run, {1, 2}, {}, 0, false);
        p.probe = [&](int baud, BaudScan::Answer answer) {
            run.probed.push_back(baud);
            kept = answer; // never answered: the scan waits at rate 1
        };
        scan.start(std::move(p));
        QTRY_COMPARE(run.probed.size(), size_t(1));
        scan.stop();
        kept(Outcome::Found); // an answer that comes after stop()
        QCOMPARE(run.found, 0);
        QVERIFY(!run.stopped); // stop() itself gives no verdict

        // A new scan is not moved on by the old scan's answer either.
        Run second;
        BaudScan::Answer old = kept;
        BaudScan::Plan q = plan(second, {7, 8}, {}, 0, false);
        q.probe = [&](int baud, BaudScan::Answer answer) {
            second.probed.push_back(baud);
            kept = answer;
        };
        scan.start(std::move(q));
        QTRY_COMPARE(second.probed.size(), size_t(1));
        old(Outcome::TryNext);
        QTest::qWait(20); // duration under test: an answer taken would probe 8 on the next 0 ms timer
        QCOMPARE(second.probed, std::vector<int>{7});
        kept(Outcome::Found);
        QCOMPARE(second.found, 7);
    }

    void exhaustedMayStartTheNextScan()
    {
        // HiPNUC's recovery: a short list first, then the whole detection from its callback.
        BaudScan scan;
        Run first;
        Run second;
        BaudScan::Plan p = plan(first, {5, 6}, {}, 0, false);
        p.exhausted = [&] {
            first.exhausted = true;
            scan.start(plan(second, {1, 2, 3}, {{3, Outcome::Found}}, 0, false));
        };
        scan.start(std::move(p));
        QTRY_COMPARE(second.found, 3);
        QCOMPARE(first.probed, (std::vector<int>{5, 6}));
        QCOMPARE(second.probed, (std::vector<int>{1, 2, 3}));
    }

    void reconnectorRetriesUntilTheLinkReopens()
    {
        FlakyTransport link;
        link.attemptsUntilBack = 3;
        device::Reconnector r(link, nullptr);
        int reopened = 0;
        r.start(460800, [&] { ++reopened; });
        QVERIFY(r.waiting());
        QTRY_COMPARE_WITH_TIMEOUT(reopened, 1, 5 * device::Reconnector::kPollMs);
        QCOMPARE(link.attempts, 3);
        QCOMPARE(link.reopenedAt, 460800); // the rate the device was last heard at
        QVERIFY(!r.waiting());
        QCOMPARE(r.count(), uint64_t(1));
        QTest::qWait(2 * device::Reconnector::kPollMs); // duration under test: two polls without an attempt
        QCOMPARE(link.attempts, 3); // no attempt after success
        r.resetCount();
        QCOMPARE(r.count(), uint64_t(0));
    }

    void reconnectorStopsWhenTurnedOff()
    {
        FlakyTransport link;
        link.attemptsUntilBack = 1000;
        device::Reconnector r(link, nullptr);
        int reopened = 0;
        r.start(9600, [&] { ++reopened; });
        QTRY_VERIFY(link.attempts >= 1);
        r.setEnabled(false);
        QVERIFY(!r.waiting());
        const int seen = link.attempts;
        QTest::qWait(2 * device::Reconnector::kPollMs); // duration under test: two polls without an attempt
        QCOMPARE(link.attempts, seen);
        r.start(9600, [&] { ++reopened; }); // disabled: does not start
        QVERIFY(!r.waiting());
        QCOMPARE(reopened, 0);
        QCOMPARE(r.count(), uint64_t(0));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstLinkHelpers)
#include "tst_link_helpers.moc"
