// imudesk-cli end to end: simulate --pty, probe, read, send, decode, exit codes.
#include "../common/cli_run.h"
#include "../common/golden.h"
#include "../common/test_main.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

namespace {

using Result = imudesk::test::CliResult;

Result run(const QStringList &args, int timeoutMs = 30000)
{
    return imudesk::test::runCli(args, timeoutMs);
}

} // namespace

class TstCli : public QObject {
    Q_OBJECT
    QProcess m_sim;
    QString m_pty;

private Q_SLOTS:
    void initTestCase()
    {
        m_sim.start(QString::fromUtf8(IMUDESK_CLI_PATH),
                    {"simulate", "--pty", "--baud", "230400", "--motion", "tumble", "--seed", "3"});
        QVERIFY(m_sim.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(m_sim.canReadLine(), 10000);
        const QString first = QString::fromUtf8(m_sim.readLine()).trimmed();
        QVERIFY2(first.startsWith(QStringLiteral("pty: /dev/")), qPrintable(first));
        m_pty = first.mid(5);
    }

    void cleanupTestCase()
    {
        ::kill(pid_t(m_sim.processId()), SIGTERM);
        QVERIFY(m_sim.waitForFinished(5000));
        QCOMPARE(m_sim.exitStatus(), QProcess::NormalExit);
        QCOMPARE(m_sim.exitCode(), 0);
    }

    void probeDetectsBaudAndIdentity()
    {
        const auto r = run({"probe", m_pty, "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const auto o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o.value("baud").toInt(), 230400);
        QCOMPARE(o.value("product").toString(), QStringLiteral("HI14R3"));
        QCOMPARE(o.value("firmware").toString(), QStringLiteral("1.7.1"));
        QVERIFY(!o.value("serial").toString().isEmpty());
        const auto text = run({"probe", m_pty, "--baud", "230400"});
        QCOMPARE(text.code, 0);
        QVERIFY2(text.out.contains(QStringLiteral("product: HI14R3")), qPrintable(text.out + text.err));
    }

    void sendPrintsReply()
    {
        const auto r = run({"send", m_pty, "--baud", "230400", "LOG VERSION"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("PNAME=HI14R3")));
        QVERIFY(r.out.contains(QStringLiteral("APP_VER=171")));
        QVERIFY(r.out.trimmed().endsWith(QStringLiteral("OK")));
    }

    void sendErrAndTimeoutFail()
    {
        const auto e = run({"send", m_pty, "--baud", "230400", "CONFIG ATT MODE 9"});
        QCOMPARE(e.code, 1);
        QVERIFY(e.err.contains(QStringLiteral("ERR")));
        QCOMPARE(e.err.trimmed().count(QLatin1Char('\n')), 0); // one line
        const auto t = run({"send", m_pty, "--baud", "230400", "--timeout", "300", "FOO BAR"});
        QCOMPARE(t.code, 1);
        QVERIFY(t.err.contains(QStringLiteral("no reply")));
    }

    void readOnce()
    {
        // Take one sample: LOG HI83 ONMARK ONCE brings one HI83 frame (the module streams HI91).
        auto r = run({"read", m_pty, "--baud", "230400", "--once", "HI83", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const auto lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1);
        QCOMPARE(QJsonDocument::fromJson(lines.front().toUtf8()).object().value("type").toString(), QStringLiteral("HI83"));
        r = run({"read", m_pty, "--baud", "230400", "--once", "FOO"});
        QCOMPARE(r.code, 2);
    }

    void readJsonLines()
    {
        const auto r = run({"read", m_pty, "--baud", "230400", "--duration", "1", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const auto lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        // A second at 100 Hz: about 100 lines when the simulator had the CPU it needed; on a
        // loaded machine fewer, but never one lost between two that came (system_time 10 ms
        // apart), and the common times in order.
        QVERIFY2(lines.size() >= 20 && lines.size() <= 120, qPrintable(QString::number(lines.size())));
        qint64 lastCommon = 0;
        int lastMs = -1;
        for (const auto &l : lines) {
            const auto o = QJsonDocument::fromJson(l.toUtf8()).object();
            QCOMPARE(o.value("type").toString(), QStringLiteral("HI91"));
            QCOMPARE(o.value("quat").toArray().size(), 4);
            const int ms = o.value("system_time").toInt();
            const qint64 common = o.value("common_time_ns").toInteger();
            if (lastMs >= 0) {
                QCOMPARE(ms - lastMs, 10);
                QVERIFY2(common > lastCommon, qPrintable(l));
            }
            lastMs = ms;
            lastCommon = common;
        }
    }

    void decodeCapture()
    {
        using namespace imudesk::protocol::hipnuc;
        QTemporaryDir dir;
        QByteArray capture;
        int intact = 0;
        for (int i = 0; i < 1000; ++i) {
            Hi91 h;
            h.systemTime = uint32_t(i);
            auto f = buildFrame(encode(h));
            if (i % 100 == 7)
                f[20] ^= 0xFF; // corrupted
            else
                ++intact;
            capture.append(reinterpret_cast<const char *>(f.data()), qsizetype(f.size()));
            if (i % 50 == 0)
                capture.append("\x5A\x00garbage", 9);
        }
        capture.append(golden::kRmc);
        capture.append("\r\n");
        const QString path = dir.filePath(QStringLiteral("capture.bin"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(capture);
        f.close();
        const auto r = run({"decode", path, "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const auto lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        int hi91 = 0;
        for (const auto &l : lines.mid(0, lines.size() - 1))
            if (QJsonDocument::fromJson(l.toUtf8()).object().value("type").toString() == QLatin1String("HI91"))
                ++hi91;
        QCOMPARE(hi91, intact);
        const auto summary = QJsonDocument::fromJson(lines.last().toUtf8()).object().value("summary").toObject();
        QCOMPARE(summary.value("frames").toObject().value("HI91").toInt(), intact);
        QCOMPARE(summary.value("frames").toObject().value("NMEA").toInt(), 1);
        QCOMPARE(summary.value("crc_errors").toInt(), 10);
        QCOMPARE(summary.value("bytes").toInt(), int(capture.size()));
        QVERIFY(summary.contains("mb_per_s"));
    }

    // Text that is not a frame is not damage: NMEA sentences and reply lines are not
    // counted as skipped bytes, noise is.
    void decodeCountsOnlyNoiseAsSkipped()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("nmea.bin"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(golden::kRmc) + "\r\nOK\r\n" + QByteArray(golden::kRmc) + "\r\n");
        f.write(QByteArray(7, '\x01'));
        f.close();
        const auto r = run({"decode", path, "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const auto lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3); // two NMEA objects and the summary
        const auto summary = QJsonDocument::fromJson(lines.last().toUtf8()).object().value("summary").toObject();
        QCOMPARE(summary.value("frames").toObject().value("NMEA").toInt(), 2);
        QCOMPARE(summary.value("bytes_skipped").toInt(), 7);
    }

    void errorsAndUsage()
    {
        const auto missing = run({"probe", "/dev/imudesk-no-such-port"});
        QCOMPARE(missing.code, 1);
        QVERIFY(missing.err.startsWith(QStringLiteral("imudesk-cli: ")));
        QVERIFY(missing.err.contains(QStringLiteral("not found")));
        // A word that is no command: one line naming it and a hint to --help, not the whole usage.
        const auto unknown = run({"frobnicate"});
        QCOMPARE(unknown.code, 2);
        const QStringList lines = unknown.err.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 2);
        QCOMPARE(lines.at(0), QStringLiteral("imudesk-cli: unknown command 'frobnicate'"));
        QVERIFY2(lines.at(1).contains(QStringLiteral("imudesk-cli --help")), qPrintable(lines.at(1)));
        QVERIFY(unknown.out.isEmpty());
        // A slip of the fingers is answered with the command it meant.
        const auto typo = run({"recrod", m_pty});
        QCOMPARE(typo.code, 2);
        QVERIFY2(typo.err.startsWith(QStringLiteral("imudesk-cli: unknown command 'recrod'; did you mean 'record'?\n")),
                 qPrintable(typo.err));
        QCOMPARE(typo.err.count(QLatin1Char('\n')), 2);
        QVERIFY2(run({"analyse", "x"}).err.contains(QStringLiteral("did you mean 'analyze'?")), "analyse");
        QVERIFY2(run({"stat"}).err.contains(QStringLiteral("did you mean 'station'?")), "stat");
        QCOMPARE(run({"send", m_pty}).code, 2);
        QCOMPARE(run({"decode", "/nonexistent/file.bin"}).code, 1);
        QCOMPARE(run({"simulate"}).code, 2);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCli)
#include "tst_cli.moc"
