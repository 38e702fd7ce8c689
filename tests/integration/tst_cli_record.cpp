// imudesk-cli record, export and analyze end to end against the simulator on a pseudo-terminal,
// and a recording that hits a file size limit (ulimit -f) stops with a message and an intact file.
#include "../common/capture_bytes.h"
#include "../common/cli_run.h"
#include "../common/test_main.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <csignal>

using namespace imudesk;

namespace {

test::CliResult run(const QStringList &args, const QString &program = QString::fromUtf8(IMUDESK_CLI_PATH),
                    int timeoutMs = 30000)
{
    return test::runProgram(program, args, timeoutMs);
}

// Chunks of a capture and how reading ended.
std::pair<int, capture::CaptureReader::Result> chunks(const QString &path)
{
    capture::CaptureReader r;
    QString error;
    if (!r.open(path, &error))
        return {-1, capture::CaptureReader::Result::Error};
    capture::CaptureReader::Chunk c;
    capture::CaptureReader::Result res;
    int n = 0;
    while ((res = r.next(c)) == capture::CaptureReader::Result::Chunk)
        ++n;
    return {n, res};
}

} // namespace

class TstCliRecord : public QObject {
    Q_OBJECT
    QProcess m_sim;
    QString m_pty;
    QTemporaryDir m_dir;
    QString m_capture;
    int m_rangeRows = -1;

private Q_SLOTS:
    void initTestCase()
    {
        m_sim.start(QString::fromUtf8(IMUDESK_CLI_PATH), {"simulate", "--pty", "--baud", "921600", "--seed", "4"});
        QVERIFY(m_sim.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(m_sim.canReadLine(), 10000);
        const QString first = QString::fromUtf8(m_sim.readLine()).trimmed();
        QVERIFY2(first.startsWith(QStringLiteral("pty: /dev/")), qPrintable(first));
        m_pty = first.mid(5);
        m_capture = m_dir.filePath(QStringLiteral("run.imucap"));
    }

    void cleanupTestCase()
    {
        ::kill(pid_t(m_sim.processId()), SIGTERM);
        QVERIFY(m_sim.waitForFinished(5000));
    }

    void recordWritesCapture()
    {
        // 3 s: the Allan curve reaches τ = 1 s from 2 s of data (analyzeJson, below)
        const auto r = run({"record", m_pty, "-o", m_capture, "--duration", "3", "--baud", "921600"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("recorded")));
        capture::CaptureReader reader;
        QString error;
        QVERIFY2(reader.open(m_capture, &error), qPrintable(error));
        QCOMPARE(reader.header().baud(), 921600);
        QCOMPARE(reader.header().identity().productName, std::string("HI14R3"));
        QCOMPARE(reader.header().config().at("HI91"), std::string("ONTIME 0.01"));
        const auto [n, end] = chunks(m_capture);
        QVERIFY(n > 20);
        QCOMPARE(end, capture::CaptureReader::Result::End);
    }

    void exportFormats_data()
    {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("firstLineStart");
        // One frame type: the vendor layout goes to the file named (no _HI91 suffix).
        QTest::newRow("vendor-csv") << "vendor-csv" << "vendor.csv" << "HI91,pc_counter,sys_time,";
        QTest::newRow("csv") << "csv" << "v.csv" << "time_s,";
        QTest::newRow("jsonl") << "jsonl" << "v.jsonl" << "{\"type\":\"HI91\"";
    }
    void exportFormats()
    {
        QFETCH(QString, format);
        QFETCH(QString, file);
        QFETCH(QString, firstLineStart);
        const QString out = m_dir.filePath(file);
        const auto r = run({"export", m_capture, "--format", format, "-o", out, "--from", "0.5", "--to", "1.5"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile f(m_dir.filePath(file));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readLine().startsWith(firstLineStart.toUtf8()));
        int rows = format == QLatin1String("jsonl") ? 1 : 0; // JSON Lines has no header line
        while (!f.atEnd())
            rows += !f.readLine().trimmed().isEmpty();
        // 1 s of arrival time at 100 Hz: fewer when a loaded machine starves the simulator, more
        // when frames held up by a stall arrive together inside the range; well short of the
        // capture's 3 s either way (the range cut works). Every format has the same rows.
        QVERIFY2(rows >= 30 && rows <= 160, qPrintable(QString::number(rows)));
        if (m_rangeRows >= 0)
            QCOMPARE(rows, m_rangeRows);
        m_rangeRows = rows;
    }

    void analyzeJson()
    {
        for (const QString &input : {m_capture, m_dir.filePath(QStringLiteral("vendor.csv"))}) {
            const auto r = run({"analyze", input, "--json", "--tau-max", "10"});
            QVERIFY2(r.code == 0, qPrintable(r.err));
            const auto o = QJsonDocument::fromJson(r.out.toUtf8()).object();
            QCOMPARE(o.value("source").toString(), QStringLiteral("HI91"));
            QVERIFY(std::abs(o.value("rate_hz").toDouble() - 100.0) < 0.5);
            QCOMPARE(o.value("frames_lost").toInt(), 0);
            QVERIFY(o.value("channels").toObject().contains("gyr_z"));
            // The capture's 3 s reach τ = 1 s; the vendor CSV's second (exportFormats' range) does not,
            // and gets no curve but the reason.
            const bool whole = input == m_capture;
            QCOMPARE(o.value("allan").toObject().value("gyr_x").toObject().value("adev").toArray().isEmpty(), !whole);
            QCOMPARE(o.value("too_short").toBool(), !whole);
            QCOMPARE(o.value("recommended_length_s").toDouble(), 510.0);
        }
    }

    void importVendorCsv()
    {
        const QString csv = m_dir.filePath(QStringLiteral("vendor.csv"));
        const QString cap = m_dir.filePath(QStringLiteral("imported.imucap"));
        const auto r = run({"import", csv, "-o", cap});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("0 malformed lines")));
        const auto [n, end] = chunks(cap);
        QCOMPARE(n, m_rangeRows); // one chunk per row of the 1 s export
        QCOMPARE(end, capture::CaptureReader::Result::End);
        // Broken rows are reported with their line numbers and left out.
        QFile f(csv);
        QVERIFY(f.open(QIODevice::Append));
        f.write("HI91,1,2,3\n");
        f.close();
        const auto bad = run({"import", csv, "-o", cap});
        QCOMPARE(bad.code, 0);
        QVERIFY2(bad.err.contains(QStringLiteral("line %1").arg(n + 2)), qPrintable(bad.err));
        QVERIFY(bad.out.contains(QStringLiteral("1 malformed lines")));
    }

    void badUsage_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("record without -o") << QStringList{"record", "/dev/null"};
        QTest::newRow("unknown format") << QStringList{"export", "x.imucap", "--format", "xls"};
        QTest::newRow("analyze two files") << QStringList{"analyze", "a", "b"};
    }
    void badUsage()
    {
        QFETCH(QStringList, args);
        QCOMPARE(run(args).code, 2);
    }

    void rawDumpLikeACapture()
    {
        // The recording's bytes alone, as a serial terminal would have saved them (named .txt):
        // export and analyze take it by its content, with the device clock for time, and say so.
        const QByteArray raw = test::receivedBytes(m_capture);
        QVERIFY(!raw.isEmpty());
        const QString dump = m_dir.filePath(QStringLiteral("terminal.txt"));
        QFile f(dump);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QCOMPARE(f.write(raw), raw.size());
        f.close();
        const auto fromCapture = run({"export", m_capture, "--format", "csv", "-o", m_dir.filePath("cap.csv")});
        const auto fromDump = run({"export", dump, "--format", "csv", "-o", m_dir.filePath("dump.csv")});
        QVERIFY2(fromDump.code == 0, qPrintable(fromDump.err));
        QVERIFY2(fromDump.err.contains(QStringLiteral("raw byte dump")), qPrintable(fromDump.err));
        QCOMPARE(fromDump.out.section(QLatin1Char('\n'), -2).trimmed(), fromCapture.out.section(QLatin1Char('\n'), -2).trimmed());
        const auto a = run({"analyze", dump, "--json"});
        QVERIFY2(a.code == 0, qPrintable(a.err));
        const auto b = run({"analyze", m_capture, "--json"});
        QCOMPARE(a.json().value("frames").toInteger(), b.json().value("frames").toInteger());
    }

    void analyzeRejectsOtherFiles()
    {
        const QString path = m_dir.filePath(QStringLiteral("notes.txt"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("hello\n");
        f.close();
        const auto r = run({"analyze", path});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains(QStringLiteral("neither an ImuDesk capture, a vendor CSV")));
    }

    void fileSizeLimitStopsRecording()
    {
        const QString prlimit = QStandardPaths::findExecutable(QStringLiteral("prlimit"));
        if (prlimit.isEmpty())
            QSKIP("prlimit (util-linux) is not installed");
        const QString path = m_dir.filePath(QStringLiteral("limited.imucap"));
        // 6 KiB: the header and a few hundred ms of HI91 at 100 Hz.
        const auto r = run({"--fsize=6144", QString::fromUtf8(IMUDESK_CLI_PATH), "record", m_pty, "-o", path,
                            "--duration", "10", "--baud", "921600"},
                           prlimit);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("Recording stopped")), qPrintable(r.err));
        QVERIFY(r.err.contains(QStringLiteral("free some disk space")));
        QVERIFY(QFileInfo(path).size() <= 6144);
        const auto [n, end] = chunks(path);
        QVERIFY(n > 0);
        QCOMPARE(end, capture::CaptureReader::Result::End); // the partial chunk was cut off
    }

    // v1.7.1 4.6.7.10: a module set to CONFIG IMU COORD 4 reports its attitude in NWU. The
    // probe says so, live JSON and text say so, and the recording's exports name their
    // attitude columns for it (the static simulator's ENU yaw 35 is NWU -55).
    void nwuModuleLabelledAsNwu()
    {
        QProcess sim;
        sim.start(QString::fromUtf8(IMUDESK_CLI_PATH), {"simulate", "--pty", "--baud", "115200"});
        QVERIFY(sim.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
        const QString pty = QString::fromUtf8(sim.readLine()).trimmed().mid(5);
        auto r = run({"probe", pty, "--json"});
        QCOMPARE(r.json().value("world_frame").toString(), QStringLiteral("ENU"));
        r = run({"config", pty, "--baud", "115200", "set", "IMU.COORD=4", "--save", "--reboot"});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        r = run({"probe", pty, "--json"});
        QCOMPARE(r.json().value("world_frame").toString(), QStringLiteral("NWU"));
        r = run({"read", pty, "--baud", "115200", "--duration", "0.3", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject o = QJsonDocument::fromJson(r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts).first().toUtf8()).object();
        QCOMPARE(o.value("world_frame").toString(), QStringLiteral("NWU"));
        QVERIFY2(std::abs(o.value("yaw").toDouble() + 55.0) < 0.5, qPrintable(r.out.left(400)));
        r = run({"read", pty, "--baud", "115200", "--duration", "0.2"});
        QVERIFY2(r.out.contains(QStringLiteral("rpy(NWU)=")), qPrintable(r.out.left(400)));
        const QString capture = m_dir.filePath(QStringLiteral("nwu.imucap"));
        r = run({"record", pty, "-o", capture, "--duration", "1", "--baud", "115200"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        ::kill(pid_t(sim.processId()), SIGTERM);
        QVERIFY(sim.waitForFinished(5000));
        const QString csv = m_dir.filePath(QStringLiteral("nwu.csv")), jsonl = m_dir.filePath(QStringLiteral("nwu.jsonl"));
        QVERIFY(run({"export", capture, "--format", "csv", "-o", csv}).code == 0);
        QFile c(csv);
        QVERIFY(c.open(QIODevice::ReadOnly));
        QVERIFY2(c.readLine().contains("mag_z_uT,roll_nwu_deg,pitch_nwu_deg,yaw_nwu_deg,quat_nwu_w"), "csv header");
        QVERIFY(run({"export", capture, "--format", "jsonl", "-o", jsonl}).code == 0);
        QFile j(jsonl);
        QVERIFY(j.open(QIODevice::ReadOnly));
        QVERIFY(j.readLine().contains("\"world_frame\":\"NWU\""));
        r = run({"export", capture, "--format", "vendor-csv", "-o", m_dir.filePath(QStringLiteral("nwuv.csv"))});
        QVERIFY2(r.code == 0 && (r.out + r.err).contains(QStringLiteral("North-West-Up")), qPrintable(r.out + r.err));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliRecord)
#include "tst_cli_record.moc"
