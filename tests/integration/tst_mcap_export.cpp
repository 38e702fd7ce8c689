// MCAP export (issue 37) read back by the official reader: tests/mcap/read_mcap.mjs runs
// @mcap/core (with @foxglove/rosmsg2-serialization for the CDR messages) on Node.js, installed
// from the lock file by the README's set-up commands (npm ci --prefix tests/mcap). The file's
// schemas, channels, metadata, attachment and message counts are checked, and every decoded
// value against the tidy CSV export of the same capture; a file cut short (a recording killed)
// still reads up to its last whole chunk.
#include "../common/cli_process.h"
#include "../common/synthetic_capture.h"
#include "../common/synthetic_session.h"
#include "../common/test_main.h"
#include "../common/test_paths.h"
#include "record/capture_exporter.h"
#include "record/session_exporter.h"
#include "record/session_manifest.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace imudesk;

namespace {

QString readerDir() { return QDir::cleanPath(QString::fromUtf8(IMUDESK_TEST_DATA) + QStringLiteral("/../mcap")); }

// The reader's JSON (its error in *error when it failed).
QJsonObject readMcap(const QString &file, const QStringList &args, QString *error)
{
    QProcess node;
    node.start(QStringLiteral("node"), QStringList{QDir(readerDir()).filePath(QStringLiteral("read_mcap.mjs")), file} + args);
    if (!node.waitForFinished(120000)) {
        *error = QStringLiteral("node did not finish: %1").arg(node.errorString());
        return {};
    }
    const QByteArray out = node.readAllStandardOutput();
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(out, &pe);
    if (!doc.isObject()) {
        *error = QStringLiteral("no JSON from the reader (%1): %2 %3")
                     .arg(pe.errorString(), QString::fromUtf8(out.left(300)), QString::fromUtf8(node.readAllStandardError()));
        return {};
    }
    if (node.exitCode() != 0)
        *error = doc.object().value(QStringLiteral("error")).toString(QStringLiteral("the reader failed"));
    return doc.object();
}

// The tidy CSV: its header's columns and its rows, split.
struct Csv {
    QHash<QString, int> column;
    std::vector<QList<QByteArray>> rows;
    bool load(const QString &path)
    {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            return false;
        const QList<QByteArray> head = f.readLine().trimmed().split(',');
        for (int i = 0; i < head.size(); ++i)
            column.insert(QString::fromUtf8(head[i]), i);
        while (!f.atEnd()) {
            const QByteArray line = f.readLine().trimmed();
            if (!line.isEmpty())
                rows.push_back(line.split(','));
        }
        return true;
    }
    QByteArray at(size_t row, const char *name) const { return rows[row].value(column.value(QLatin1String(name), -1)); }
};

bool near(double mcap, const QByteArray &csv)
{
    // The CSV holds the single-precision value as float text; the file the double of it.
    const double v = csv.toDouble();
    return std::abs(mcap - v) <= 1e-6 * std::max(1.0, std::abs(v));
}

QString at(const QJsonObject &o, const char *a, const char *b = nullptr)
{
    QJsonValue v = o.value(QLatin1String(a));
    if (b)
        v = v.toObject().value(QLatin1String(b));
    return QString::number(v.toDouble(), 'g', 17);
}

} // namespace

class TstMcapExport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_capture, m_csv, m_mcap;
    QString m_killed;
    qlonglong m_killedMessages = 0;

private Q_SLOTS:
    void initTestCase()
    {
        if (!QFile::exists(QDir(readerDir()).filePath(QStringLiteral("node_modules/@mcap/core/package.json"))))
            QFAIL(qPrintable(QStringLiteral("The official MCAP reader is not installed in %1: run `npm ci --prefix "
                                            "tests/mcap` (the README's set-up commands do).")
                                 .arg(readerDir())));
        synthetic::CaptureSpec spec;
        spec.frames = 3000; // 3 s at 1 kHz: three or more chunks
        spec.mixed = true;  // HI81 (a GNSS position) and HI83 beside HI91, and NMEA
        spec.serial = "SN-0042/a";
        spec.config = {{"baud", "921600"}, {"log", "HI91 ONTIME 0.001"}, {"mode", "9-axis"}};
        m_capture = m_dir.filePath(QStringLiteral("run.imucap"));
        QVERIFY(synthetic::writeCapture(m_capture, spec) > 0);
        record::CaptureExporter::Options o;
        o.format = record::CaptureExporter::Format::TidyCsv;
        o.output = m_csv = m_dir.filePath(QStringLiteral("run.csv"));
        auto r = record::CaptureExporter::run(m_capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        o.format = record::CaptureExporter::Format::Mcap;
        o.output = m_mcap = m_dir.filePath(QStringLiteral("run.mcap"));
        r = record::CaptureExporter::run(m_capture, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.files, QStringList{m_mcap});
    }

    void summaryAsWritten()
    {
        QString error;
        const QJsonObject f = readMcap(m_mcap, {QStringLiteral("--messages"), QStringLiteral("0")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(f.value(QStringLiteral("profile")).toString(), QStringLiteral("ros2"));
        QVERIFY(f.value(QStringLiteral("library")).toString().startsWith(QStringLiteral("ImuDesk")));
        QStringList schemas;
        for (const QJsonValue v : f.value(QStringLiteral("schemas")).toArray())
            schemas << v.toObject().value(QStringLiteral("name")).toString() + QLatin1Char(' ')
                    + v.toObject().value(QStringLiteral("encoding")).toString();
        schemas.sort();
        schemas.move(schemas.indexOf(QStringLiteral("geometry_msgs/msg/Vector3Stamped ros2msg")), schemas.size() - 1);
        QCOMPARE(schemas, (QStringList{QStringLiteral("imudesk/Sample jsonschema"), QStringLiteral("sensor_msgs/msg/FluidPressure ros2msg"),
                                       QStringLiteral("sensor_msgs/msg/Imu ros2msg"), QStringLiteral("sensor_msgs/msg/MagneticField ros2msg"),
                                       QStringLiteral("sensor_msgs/msg/NavSatFix ros2msg"), QStringLiteral("sensor_msgs/msg/Temperature ros2msg"),
                                       QStringLiteral("tf2_msgs/msg/TFMessage ros2msg"),
                                       QStringLiteral("geometry_msgs/msg/Vector3Stamped ros2msg")}));
        QStringList topics;
        for (const QJsonValue v : f.value(QStringLiteral("channels")).toArray()) {
            const QJsonObject c = v.toObject();
            topics << c.value(QStringLiteral("topic")).toString();
            if (c.value(QStringLiteral("topic")).toString() != QLatin1String("/tf"))
                QCOMPARE(c.value(QStringLiteral("metadata")).toObject().value(QStringLiteral("serial")).toString(),
                         QStringLiteral("SN-0042/a"));
        }
        topics.sort();
        QCOMPARE(topics, (QStringList{QStringLiteral("/imu/SN_0042_a/euler"), QStringLiteral("/imu/SN_0042_a/fix"), QStringLiteral("/imu/SN_0042_a/imu"),
                                      QStringLiteral("/imu/SN_0042_a/mag"), QStringLiteral("/imu/SN_0042_a/pressure"),
                                      QStringLiteral("/imu/SN_0042_a/status"), QStringLiteral("/imu/SN_0042_a/temperature"),
                                      QStringLiteral("/tf")}));
        // The device as metadata, its configuration as an attachment.
        bool device = false;
        for (const QJsonValue v : f.value(QStringLiteral("metadata")).toArray())
            if (v.toObject().value(QStringLiteral("name")).toString() == QLatin1String("device")) {
                const QJsonObject m = v.toObject().value(QStringLiteral("metadata")).toObject();
                QCOMPARE(m.value(QStringLiteral("product")).toString(), QStringLiteral("HI14R3"));
                QCOMPARE(m.value(QStringLiteral("baud")).toString(), QStringLiteral("921600"));
                device = true;
            }
        QVERIFY(device);
        const QJsonArray attachments = f.value(QStringLiteral("attachments")).toArray();
        QCOMPARE(attachments.size(), 1);
        const QJsonObject a = attachments.at(0).toObject();
        QCOMPARE(a.value(QStringLiteral("name")).toString(), QStringLiteral("configuration.json"));
        QCOMPARE(a.value(QStringLiteral("mediaType")).toString(), QStringLiteral("application/json"));
        const QJsonObject config = QJsonDocument::fromJson(a.value(QStringLiteral("text")).toString().toUtf8()).object();
        QCOMPARE(config.value(QStringLiteral("log")).toString(), QStringLiteral("HI91 ONTIME 0.001"));
        // One message per sample on the status channel, one per sample with its quantity on the
        // others: the rows of the tidy CSV.
        Csv csv;
        QVERIFY(csv.load(m_csv));
        size_t withImu = 0, withMag = 0, withFix = 0, withEuler = 0;
        for (size_t i = 0; i < csv.rows.size(); ++i) {
            withEuler += !csv.at(i, "roll_deg").isEmpty();
            withImu += !csv.at(i, "acc_x_mps2").isEmpty() || !csv.at(i, "gyr_x_radps").isEmpty() || !csv.at(i, "quat_w").isEmpty();
            withMag += !csv.at(i, "mag_x_uT").isEmpty();
            withFix += !csv.at(i, "lat_deg").isEmpty();
        }
        QVERIFY(withFix > 0);
        const QJsonObject stats = f.value(QStringLiteral("statistics")).toObject();
        const QJsonObject perChannel = stats.value(QStringLiteral("channelMessageCounts")).toObject();
        QHash<QString, qlonglong> count;
        qlonglong total = 0;
        for (const QJsonValue v : f.value(QStringLiteral("channels")).toArray()) {
            const QJsonObject c = v.toObject();
            const qlonglong n = perChannel.value(QString::number(c.value(QStringLiteral("id")).toInt())).toString().toLongLong();
            count.insert(c.value(QStringLiteral("topic")).toString().section(QLatin1Char('/'), -1), n);
            total += n;
        }
        // The status: ten times a second, and at each change of the status word (this capture's
        // changes every frame) or sample with more than the status word and time.
        QVERIFY(count.value(QStringLiteral("status")) >= 30 && count.value(QStringLiteral("status")) <= qlonglong(csv.rows.size()));
        QCOMPARE(count.value(QStringLiteral("euler")), qlonglong(withEuler));
        QCOMPARE(count.value(QStringLiteral("imu")), qlonglong(withImu));
        QCOMPARE(count.value(QStringLiteral("mag")), qlonglong(withMag));
        QCOMPARE(count.value(QStringLiteral("fix")), qlonglong(withFix));
        QCOMPARE(stats.value(QStringLiteral("messageCount")).toString().toLongLong(), total);
        QVERIFY(f.value(QStringLiteral("chunkCount")).toInt() >= 3); // a chunk spans a second at most
    }

    void valuesEqualTheTidyCsv()
    {
        QString error;
        const QJsonObject f = readMcap(m_mcap, {}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        Csv csv;
        QVERIFY(csv.load(m_csv));
        // Each topic's messages in order against the CSV rows that have its quantity.
        QHash<QString, std::vector<QJsonObject>> byTopic;
        for (const QJsonValue v : f.value(QStringLiteral("messages")).toArray()) {
            const QJsonObject m = v.toObject();
            byTopic[m.value(QStringLiteral("topic")).toString().section(QLatin1Char('/'), -1)].push_back(m);
        }
        size_t imu = 0, mag = 0, fix = 0, checked = 0;
        const auto &imuMsgs = byTopic[QStringLiteral("imu")];
        const auto &magMsgs = byTopic[QStringLiteral("mag")];
        const auto &fixMsgs = byTopic[QStringLiteral("fix")];
        const auto &eulerMsgs = byTopic[QStringLiteral("euler")];
        size_t euler = 0;
        double publish0 = -1, common0 = 0;
        for (size_t i = 0; i < csv.rows.size(); ++i) {
            const QString where = QStringLiteral("row %1").arg(i);
            if (!csv.at(i, "roll_deg").isEmpty()) {
                QVERIFY2(euler < eulerMsgs.size(), qPrintable(where));
                const QJsonObject &m = eulerMsgs[euler++];
                // The sample's time: publish_time is its common time, the CSV's common_time_s.
                const double publish = m.value(QStringLiteral("publishTime")).toString().toDouble();
                if (!csv.at(i, "common_time_s").isEmpty()) {
                    if (publish0 < 0) {
                        publish0 = publish;
                        common0 = csv.at(i, "common_time_s").toDouble();
                    }
                    QVERIFY2(std::abs((publish - publish0) / 1e9 - (csv.at(i, "common_time_s").toDouble() - common0)) < 2e-6,
                             qPrintable(where));
                }
                const QJsonObject v = m.value(QStringLiteral("data")).toObject().value(QStringLiteral("vector")).toObject();
                QVERIFY2(near(v.value(QStringLiteral("x")).toDouble(), csv.at(i, "roll_deg"))
                             && near(v.value(QStringLiteral("y")).toDouble(), csv.at(i, "pitch_deg"))
                             && near(v.value(QStringLiteral("z")).toDouble(), csv.at(i, "yaw_deg")),
                         qPrintable(where + QStringLiteral(" euler")));
            }
            if (!csv.at(i, "acc_x_mps2").isEmpty() || !csv.at(i, "gyr_x_radps").isEmpty() || !csv.at(i, "quat_w").isEmpty()) {
                QVERIFY2(imu < imuMsgs.size(), qPrintable(where));
                const QJsonObject d = imuMsgs[imu++].value(QStringLiteral("data")).toObject();
                if (!csv.at(i, "acc_x_mps2").isEmpty()) {
                    const QJsonObject a = d.value(QStringLiteral("linear_acceleration")).toObject();
                    QVERIFY2(near(a.value(QStringLiteral("x")).toDouble(), csv.at(i, "acc_x_mps2"))
                                 && near(a.value(QStringLiteral("y")).toDouble(), csv.at(i, "acc_y_mps2"))
                                 && near(a.value(QStringLiteral("z")).toDouble(), csv.at(i, "acc_z_mps2")),
                             qPrintable(where + QStringLiteral(" acc ") + at(d, "linear_acceleration", "x")));
                }
                if (!csv.at(i, "gyr_x_radps").isEmpty()) {
                    const QJsonObject g = d.value(QStringLiteral("angular_velocity")).toObject();
                    QVERIFY2(near(g.value(QStringLiteral("x")).toDouble(), csv.at(i, "gyr_x_radps"))
                                 && near(g.value(QStringLiteral("z")).toDouble(), csv.at(i, "gyr_z_radps")),
                             qPrintable(where + QStringLiteral(" gyr")));
                }
                if (!csv.at(i, "quat_w").isEmpty()) {
                    const QJsonObject q = d.value(QStringLiteral("orientation")).toObject();
                    QVERIFY2(near(q.value(QStringLiteral("w")).toDouble(), csv.at(i, "quat_w"))
                                 && near(q.value(QStringLiteral("x")).toDouble(), csv.at(i, "quat_x"))
                                 && near(q.value(QStringLiteral("y")).toDouble(), csv.at(i, "quat_y"))
                                 && near(q.value(QStringLiteral("z")).toDouble(), csv.at(i, "quat_z")),
                             qPrintable(where + QStringLiteral(" quat")));
                } else {
                    // Not available: ROS says so with covariance[0] = -1.
                    QCOMPARE(d.value(QStringLiteral("orientation_covariance")).toArray().at(0).toDouble(), -1.0);
                }
                ++checked;
            }
            if (!csv.at(i, "mag_x_uT").isEmpty()) {
                QVERIFY2(mag < magMsgs.size(), qPrintable(where));
                const QJsonObject m =
                    magMsgs[mag++].value(QStringLiteral("data")).toObject().value(QStringLiteral("magnetic_field")).toObject();
                QVERIFY2(near(m.value(QStringLiteral("x")).toDouble() * 1e6, csv.at(i, "mag_x_uT"))
                             && near(m.value(QStringLiteral("z")).toDouble() * 1e6, csv.at(i, "mag_z_uT")),
                         qPrintable(where + QStringLiteral(" mag")));
            }
            if (!csv.at(i, "lat_deg").isEmpty()) {
                QVERIFY2(fix < fixMsgs.size(), qPrintable(where));
                const QJsonObject d = fixMsgs[fix++].value(QStringLiteral("data")).toObject();
                QVERIFY2(std::abs(d.value(QStringLiteral("latitude")).toDouble() - csv.at(i, "lat_deg").toDouble()) < 1e-7
                             && std::abs(d.value(QStringLiteral("longitude")).toDouble() - csv.at(i, "lon_deg").toDouble()) < 1e-7,
                         qPrintable(where + QStringLiteral(" fix")));
            }
        }
        QCOMPARE(euler, eulerMsgs.size());
        QVERIFY(publish0 >= 0);
        // The status channel: main_status as the CSV has it at the sample it was written with.
        const auto &status = byTopic[QStringLiteral("status")];
        QVERIFY(!status.empty());
        QVERIFY(status.front().value(QStringLiteral("data")).toObject().contains(QStringLiteral("main_status")));
        QCOMPARE(imu, imuMsgs.size());
        QCOMPARE(mag, magMsgs.size());
        QCOMPARE(fix, fixMsgs.size());
        QVERIFY(checked > 2000);

        // A file's pressure and temperature (issue 54, point 7): a message when the value changes,
        // none while it stays, and no change dropped. Walking the rows: each change of the CSV's
        // value is the next message's value (the messages between are values the CSV prints
        // alike, if any).
        const auto onChange = [&](const char *column, const QString &topic, const char *field) {
            const auto &msgs = byTopic[topic];
            QVERIFY2(!msgs.empty(), column);
            const auto valueOf = [&](size_t m) { return msgs[m].value(QStringLiteral("data")).toObject().value(QLatin1String(field)).toDouble(); };
            size_t m = 0, rows = 0, changes = 0;
            QByteArray last;
            for (size_t i = 0; i < csv.rows.size(); ++i) {
                const QByteArray v = csv.at(i, column);
                if (v.isEmpty())
                    continue;
                ++rows;
                if (v == last)
                    continue;
                ++changes;
                while (m < msgs.size() && !last.isEmpty() && near(valueOf(m), last) && !near(valueOf(m), v))
                    ++m; // a value the CSV prints as the one before
                QVERIFY2(m < msgs.size() && near(valueOf(m), v),
                         qPrintable(QStringLiteral("%1 row %2: %3, message %4 of %5").arg(QLatin1String(column)).arg(i).arg(QString::fromUtf8(v)).arg(m).arg(msgs.size())));
                ++m;
                last = v;
            }
            QCOMPARE(m, msgs.size());
            QVERIFY2(msgs.size() < rows || changes == rows, qPrintable(QStringLiteral("%1: %2 messages for %3 rows").arg(QLatin1String(column)).arg(msgs.size()).arg(rows)));
        };
        onChange("pressure_Pa", QStringLiteral("pressure"), "fluid_pressure");
        onChange("temperature_degC", QStringLiteral("temperature"), "temperature");
        // HI91's temperature changes once a second here (HI83's, every tenth frame, differs): far
        // fewer messages than samples.
        QVERIFY2(byTopic[QStringLiteral("temperature")].size() < csv.rows.size() / 3,
                 qPrintable(QString::number(byTopic[QStringLiteral("temperature")].size())));
    }

    // What a recording killed mid-write leaves: everything up to the last whole chunk reads.
    void cutShortReadsUpToTheLastChunk()
    {
        QFile whole(m_mcap);
        QVERIFY(whole.open(QIODevice::ReadOnly));
        const QByteArray bytes = whole.readAll();
        const QString cut = m_dir.filePath(QStringLiteral("cut.mcap"));
        QFile part(cut);
        QVERIFY(part.open(QIODevice::WriteOnly));
        part.write(bytes.left(bytes.size() * 2 / 3));
        part.close();
        QString error;
        const QJsonObject all = readMcap(m_mcap, {QStringLiteral("--stream")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(all.value(QStringLiteral("complete")).toBool());
        const QJsonObject f = readMcap(cut, {QStringLiteral("--stream")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(!f.value(QStringLiteral("complete")).toBool());
        const qlonglong n = f.value(QStringLiteral("messageCount")).toString().toLongLong();
        const qlonglong total = all.value(QStringLiteral("messageCount")).toString().toLongLong();
        QVERIFY2(n > 0 && n < total, qPrintable(QStringLiteral("%1 of %2").arg(n).arg(total)));
        // Two thirds of the bytes hold two thirds of the messages, less at most the chunk cut (a
        // second of data at most).
        const double spanAll = (all.value(QStringLiteral("messageEndTime")).toString().toDouble()
                                - all.value(QStringLiteral("messageStartTime")).toString().toDouble()) / 1e9;
        const double span = (f.value(QStringLiteral("messageEndTime")).toString().toDouble()
                             - f.value(QStringLiteral("messageStartTime")).toString().toDouble()) / 1e9;
        QVERIFY2(span >= spanAll * 2 / 3 - 1.05, qPrintable(QStringLiteral("%1 s of %2 s").arg(span).arg(spanAll)));
    }

    // A live MCAP recording of a simulated module at 1 kHz, killed (SIGKILL) after 30 s: the file,
    // never closed, reads in the official reader up to its last closed chunk, 29 s or more.
    void killedRecordingKeepsAllButItsLastSecond()
    {
        QProcess sim;
        const QString ptyPath = test::startPtySimulator(sim, 1, QStringLiteral("LOG HI91 ONTIME 0.001"));
        QVERIFY(!ptyPath.isEmpty());
        const QString out = m_dir.filePath(QStringLiteral("killed.mcap"));
        QProcess rec;
        QVERIFY(test::startCliUntil(rec, {QStringLiteral("record"), ptyPath, QStringLiteral("--baud"), QStringLiteral("921600"),
                                          QStringLiteral("-o"), out, QStringLiteral("--duration"), QStringLiteral("120")},
                                    "recording ", 15000));
        QElapsedTimer t;
        t.start();
        QTest::qWait(30000); // the duration under test: 30 s recorded, then the process killed
        rec.kill();
        rec.waitForFinished(5000);
        test::stopCli(sim);
        QString error;
        const QJsonObject f = readMcap(out, {QStringLiteral("--stream")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(!f.value(QStringLiteral("complete")).toBool()); // no summary, no footer: killed
        const double span = (f.value(QStringLiteral("messageEndTime")).toString().toDouble()
                             - f.value(QStringLiteral("messageStartTime")).toString().toDouble()) / 1e9;
        const qlonglong imu = f.value(QStringLiteral("channelMessageCounts")).toObject().value(QStringLiteral("1")).toString().toLongLong();
        qInfo("killed after %.1f s: %.2f s of messages, %lld on the first channel", double(t.elapsed()) / 1000.0, span, imu);
        QVERIFY2(span >= 29.0, qPrintable(QStringLiteral("%1 s of messages").arg(span)));
        QVERIFY2(imu >= 28000, qPrintable(QString::number(imu))); // 1 kHz
        m_killed = out;
        m_killedMessages = f.value(QStringLiteral("messageCount")).toString().toLongLong();
    }

    // imudesk-cli repair completes it: the indexed reader (summary, indexes) opens it with every
    // message the stream had, the device's metadata and attachment kept.
    void repairCompletesAKilledRecording()
    {
        if (m_killed.isEmpty())
            QSKIP("needs the killed recording of the test before");
        QProcess cli;
        cli.start(QString::fromUtf8(IMUDESK_CLI_PATH), {QStringLiteral("repair"), m_killed});
        QVERIFY(cli.waitForFinished(60000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        QVERIFY(cli.readAllStandardOutput().startsWith("repaired "));
        QString error;
        const QJsonObject f = readMcap(m_killed, {QStringLiteral("--messages"), QStringLiteral("0")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(f.value(QStringLiteral("statistics")).toObject().value(QStringLiteral("messageCount")).toString().toLongLong(),
                 m_killedMessages);
        QCOMPARE(f.value(QStringLiteral("attachments")).toArray().size(), 1);
        QCOMPARE(f.value(QStringLiteral("metadata")).toArray().size(), 2);
        const QJsonObject stream = readMcap(m_killed, {QStringLiteral("--stream")}, &error);
        QVERIFY(stream.value(QStringLiteral("complete")).toBool());
        // Not an MCAP file: said, and nothing written.
        cli.start(QString::fromUtf8(IMUDESK_CLI_PATH), {QStringLiteral("repair"), m_csv, QStringLiteral("-o"),
                                                         m_dir.filePath(QStringLiteral("no.mcap"))});
        QVERIFY(cli.waitForFinished(30000));
        QCOMPARE(cli.exitCode(), 1);
        QVERIFY(cli.readAllStandardError().contains("not an MCAP file"));
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("no.mcap"))));
    }

    // A recorded session of two modules exports to one MCAP file: each module's channels under its
    // serial number, every sample once, the devices' metadata and configurations, session.json.
    void sessionToOneFile()
    {
        const QString folder = m_dir.filePath(QStringLiteral("session"));
        record::SessionManifest manifest;
        QString error;
        QVERIFY2(test::writeTwoDeviceSession(folder, &manifest, &error), qPrintable(error));
        record::SessionExporter::Options o;
        o.format = record::CaptureExporter::Format::Mcap;
        o.output = m_dir.filePath(QStringLiteral("session.mcap"));
        const auto r = record::SessionExporter::run(folder, o);
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.samplesByDevice, (std::vector<uint64_t>{1000, 1500}));
        QCOMPARE(r.rows, uint64_t(2500));
        const QJsonObject f = readMcap(o.output, {QStringLiteral("--messages"), QStringLiteral("0")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const QJsonObject perChannel = f.value(QStringLiteral("statistics")).toObject().value(QStringLiteral("channelMessageCounts")).toObject();
        QHash<QString, qlonglong> count;
        for (const QJsonValue v : f.value(QStringLiteral("channels")).toArray()) {
            const QJsonObject c = v.toObject();
            count.insert(c.value(QStringLiteral("topic")).toString(),
                         perChannel.value(QString::number(c.value(QStringLiteral("id")).toInt())).toString().toLongLong());
        }
        QCOMPARE(count.value(QStringLiteral("/imu/AAA1/imu")), 1000);
        QCOMPARE(count.value(QStringLiteral("/imu/BBB2/imu")), 1500);
        QCOMPARE(count.value(QStringLiteral("/imu/BBB2/euler")), 1500);
        QStringList attachments, metadata;
        for (const QJsonValue v : f.value(QStringLiteral("attachments")).toArray())
            attachments << v.toObject().value(QStringLiteral("name")).toString();
        for (const QJsonValue v : f.value(QStringLiteral("metadata")).toArray())
            metadata << v.toObject().value(QStringLiteral("name")).toString();
        attachments.sort();
        metadata.sort();
        QCOMPARE(attachments, (QStringList{QStringLiteral("AAA1/configuration.json"), QStringLiteral("BBB2/configuration.json"),
                                           QStringLiteral("session.json")}));
        QCOMPARE(metadata, (QStringList{QStringLiteral("device AAA1"), QStringLiteral("device BBB2"), QStringLiteral("session"),
                                        QStringLiteral("time")}));
        // On the Unix epoch from the session's start: the first message a few seconds after 20:00:00.
        const double start = f.value(QStringLiteral("statistics")).toObject().value(QStringLiteral("messageStartTime")).toString().toDouble() / 1e9;
        const double expected = double(QDateTime::fromString(manifest.startedUtc, Qt::ISODateWithMs).toSecsSinceEpoch());
        QVERIFY2(start > expected && start < expected + 1.0, qPrintable(QString::number(start - expected)));
    }

    void fromTheCommandLine()
    {
        const QString out = m_dir.filePath(QStringLiteral("cli.mcap"));
        QProcess cli;
        cli.start(QString::fromUtf8(IMUDESK_CLI_PATH),
                  {QStringLiteral("export"), m_capture, QStringLiteral("--format"), QStringLiteral("mcap"), QStringLiteral("-o"), out});
        QVERIFY(cli.waitForFinished(60000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        QString error;
        const QJsonObject f = readMcap(out, {QStringLiteral("--messages"), QStringLiteral("0")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const QJsonObject mine = readMcap(m_mcap, {QStringLiteral("--messages"), QStringLiteral("0")}, &error);
        QCOMPARE(f.value(QStringLiteral("statistics")).toObject().value(QStringLiteral("messageCount")),
                 mine.value(QStringLiteral("statistics")).toObject().value(QStringLiteral("messageCount")));
    }

    // Two live modules (HI91 at 500 Hz each) recorded into one MCAP file: each one's channels
    // under its own name, as many Imu messages as samples the recording says it wrote, none missed.
    void severalDevicesLiveIntoOneFile()
    {
        std::vector<std::unique_ptr<QProcess>> sims;
        QStringList ports;
        for (int i = 0; i < 2; ++i) {
            auto sim = std::make_unique<QProcess>();
            const QString pty = test::startPtySimulator(*sim, i + 3, QStringLiteral("LOG HI91 ONTIME 0.002"));
            QVERIFY(!pty.isEmpty());
            ports << pty + QStringLiteral(":921600");
            sims.push_back(std::move(sim));
        }
        const QString out = m_dir.filePath(QStringLiteral("two.mcap"));
        QProcess rec;
        rec.start(QString::fromUtf8(IMUDESK_CLI_PATH), {QStringLiteral("record"), ports.join(QLatin1Char(',')), QStringLiteral("-o"), out,
                                                         QStringLiteral("--duration"), QStringLiteral("4")});
        QVERIFY(rec.waitForFinished(60000));
        const QString said = QString::fromUtf8(rec.readAllStandardOutput());
        for (auto &s : sims)
            test::stopCli(*s);
        QVERIFY2(rec.exitCode() == 0, qPrintable(said + QString::fromUtf8(rec.readAllStandardError())));
        QVERIFY2(said.contains(QStringLiteral(", 0 samples missed")), qPrintable(said));
        QString error;
        const QJsonObject f = readMcap(out, {QStringLiteral("--messages"), QStringLiteral("0")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const QJsonObject perChannel = f.value(QStringLiteral("statistics")).toObject().value(QStringLiteral("channelMessageCounts")).toObject();
        QMap<QString, qlonglong> imu;
        for (const QJsonValue v : f.value(QStringLiteral("channels")).toArray()) {
            const QJsonObject c = v.toObject();
            const QString topic = c.value(QStringLiteral("topic")).toString();
            if (topic.endsWith(QLatin1String("/imu")))
                imu.insert(topic, perChannel.value(QString::number(c.value(QStringLiteral("id")).toInt())).toString().toLongLong());
        }
        QCOMPARE(imu.size(), 2);
        // "  PORT: N samples", in the order given.
        QList<qlonglong> written;
        const QRegularExpression line(QStringLiteral(": (\\d+) samples"));
        for (auto m = line.globalMatch(said); m.hasNext();)
            written << m.next().captured(1).toLongLong();
        QCOMPARE(written.size(), 2);
        QList<qlonglong> counted = imu.values();
        std::sort(counted.begin(), counted.end());
        std::sort(written.begin(), written.end());
        QCOMPARE(counted, written);
        for (qlonglong n : counted)
            QVERIFY2(n >= 1500, qPrintable(QString::number(n))); // 4 s at 500 Hz, less the start
        QStringList metadata;
        for (const QJsonValue v : f.value(QStringLiteral("metadata")).toArray())
            metadata << v.toObject().value(QStringLiteral("name")).toString();
        QCOMPARE(metadata.filter(QStringLiteral("device ")).size(), 2);
    }
};

IMUDESK_TEST_MAIN(TstMcapExport)
#include "tst_mcap_export.moc"
