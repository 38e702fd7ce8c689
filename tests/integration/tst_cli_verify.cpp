// imudesk-cli verify as a process (issue 55): a vendor CSV of a module turned by hand through
// still poses (written by the vendor's CSV layout from the simulator's sensor model, errors
// injected), the same file imported as a capture, a hand-waved recording with no still pose,
// a live module on a pseudo-terminal, and bad arguments. Exit codes: 0 pass, 1 fail or warn,
// 2 cannot judge (and usage).
#include "../common/cli_run.h"
#include "../common/motion_csv.h"
#include "../common/test_main.h"
#include "../common/verify_rig.h"
#include "decode/hipnuc_vendor_csv.h"
#include "sim/hec495_simulator.h"
#include "sim/hipnuc_simulator.h"
#include "sim/pty_simulator.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;

namespace {

// The module's samples as the vendor's PC tool writes its HI91 output (200 Hz: whole ms).
bool writeVendorCsv(const QString &path, const test::HandTurnedModule &module)
{
    std::string text = decode::vendor_csv::hi91Header();
    text += '\n';
    for (const verify::MotionSample &s : module.record()) {
        protocol::hipnuc::Hi91 h;
        h.temperature = 30;
        h.pressure = 100000;
        h.systemTime = uint32_t(std::lround(s.tS * 1000));
        for (int a = 0; a < 3; ++a) {
            h.acc[size_t(a)] = float(s.acc[a]);
            h.gyr[size_t(a)] = float(s.gyr[a]);
            h.mag[size_t(a)] = float(s.mag[a]);
        }
        const model::Euler e = sim::eulerEnu312(s.q);
        h.roll = float(e.roll);
        h.pitch = float(e.pitch);
        h.yaw = float(e.yaw);
        h.quat = {float(s.q.w()), float(s.q.x()), float(s.q.y()), float(s.q.z())};
        decode::vendor_csv::appendRow(text, h, s.tS * 1000);
    }
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text.data(), qint64(text.size())) == qint64(text.size());
}

test::HandTurnedModule module(uint64_t seed)
{
    test::HandTurnedModule m;
    m.seed = seed;
    m.rateHz = 200;
    return m;
}

} // namespace

class TstCliVerify : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void goodModulePasses()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("good.csv"));
        QVERIFY(writeVendorCsv(csv, module(61)));
        const auto r = test::runCli({QStringLiteral("verify"), csv, QStringLiteral("--gravity"), QStringLiteral("9.8")});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QLatin1String("verdict: pass")), qPrintable(r.out));
        QVERIFY(r.out.contains(QLatin1String("12 distinct poses")));
        QVERIFY(r.out.contains(QLatin1String("vendor CSV")));
    }

    // A 3° heading bias and accelerometer errors: the figures in the JSON the issue names, the
    // verdict fail, exit 1; the same file imported as a capture gives the same figures.
    void wrongModuleFailsWithItsFigures()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("wrong.csv"));
        test::HandTurnedModule m = module(62);
        m.attitudeBiasDeg = {0.2, -0.1, 3.0};
        m.accError.biasG = {0.015, 0, -0.010};
        m.accError.scale = {0.003, 0, 0};
        QVERIFY(writeVendorCsv(csv, m));
        const auto r = test::runCli({QStringLiteral("verify"), csv, QStringLiteral("--latitude"), QStringLiteral("34.2"),
                                     QStringLiteral("--json")});
        QVERIFY2(r.code == 1, qPrintable(r.out + r.err));
        const QJsonObject j = r.json();
        QCOMPARE(j.value(QLatin1String("verdict")).toString(), QStringLiteral("fail"));
        QCOMPARE(j.value(QLatin1String("poses")).toInt(), 12);
        // Latitude 34.2°: normal gravity 9.7967 m/s², 0.03 % below the simulator's 9.8, which the
        // scale figures then show on every axis.
        QVERIFY(std::fabs(j.value(QLatin1String("gravity_m_s2")).toDouble() - 9.79668) < 1e-4);
        const QJsonArray bias = j.value(QLatin1String("acc_bias_mg")).toArray();
        QCOMPARE(bias.size(), 3);
        QVERIFY2(std::fabs(bias[0].toDouble() - 15) < 1 && std::fabs(bias[2].toDouble() + 10) < 1,
                 qPrintable(QJsonDocument(bias).toJson()));
        QCOMPARE(j.value(QLatin1String("acc_bias_mg_sigma")).toArray().size(), 3);
        const QJsonArray scale = j.value(QLatin1String("acc_scale_error_pct")).toArray();
        QVERIFY2(std::fabs(scale[0].toDouble() - (0.3 + 0.034)) < 0.05, qPrintable(QJsonDocument(scale).toJson()));
        QVERIFY(j.value(QLatin1String("gyro_bias_dps")).isArray());
        QVERIFY(j.value(QLatin1String("gyro_scale_error_pct")).isArray());
        const QJsonObject att = j.value(QLatin1String("attitude_error_deg")).toObject();
        QVERIFY2(std::fabs(att.value(QLatin1String("heading")).toDouble() - 3.0) < 0.3, qPrintable(r.out));
        QVERIFY(std::fabs(att.value(QLatin1String("roll")).toDouble() - 0.2) < 0.05);
        QVERIFY(att.value(QLatin1String("heading_sigma")).toDouble() > 0);
        QVERIFY(j.value(QLatin1String("dynamic")).toObject().contains(QLatin1String("rms_deg")));
        QVERIFY(j.value(QLatin1String("reasons")).toArray().first().toString().startsWith(QLatin1String("heading error")));

        const QString cap = dir.filePath(QStringLiteral("wrong.imucap"));
        const auto imported = test::runCli({QStringLiteral("import"), csv, QStringLiteral("-o"), cap});
        QVERIFY2(imported.code == 0, qPrintable(imported.err));
        const auto c = test::runCli({QStringLiteral("verify"), cap, QStringLiteral("--latitude"), QStringLiteral("34.2"),
                                     QStringLiteral("--json")});
        QCOMPARE(c.code, 1);
        const QJsonObject k = c.json();
        QCOMPARE(k.value(QLatin1String("poses")).toInt(), 12);
        QVERIFY(std::fabs(k.value(QLatin1String("attitude_error_deg")).toObject().value(QLatin1String("heading")).toDouble()
                          - att.value(QLatin1String("heading")).toDouble())
                < 1e-6);
    }

    // Waved about by hand, never still: cannot judge, exit 2, and what to do.
    void handWavedCannotJudge()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("waved.csv"));
        QVERIFY(motion_csv::write(csv, motion_csv::Motion::ByHand, 30));
        const auto r = test::runCli({QStringLiteral("verify"), csv, QStringLiteral("--json")});
        QVERIFY2(r.code == 2, qPrintable(r.out + r.err));
        const QJsonObject j = r.json();
        QCOMPARE(j.value(QLatin1String("verdict")).toString(), QStringLiteral("cannot judge"));
        QCOMPARE(j.value(QLatin1String("poses")).toInt(), 0);
        QVERIFY(j.value(QLatin1String("acc_bias_mg")).isNull());
        QVERIFY2(j.value(QLatin1String("acc_bias_mg_why")).toString().contains(QLatin1String("no still pose: hold the module still")),
                 qPrintable(r.out));
    }

    // A live module on a pseudo-terminal turned through its first poses: the samples are read
    // and judged; too few poses for a verdict (exit 2), the gyro's bias is the simulator's.
    void livePortJudgesWhatItSaw()
    {
        sim::SimOptions o;
        o.motion = sim::Motion::Poses;
        o.seed = 63;
        sim::PtySimulator pty(o);
        QString error;
        QVERIFY2(pty.start(&error), qPrintable(error));
        const auto r = test::runCli({QStringLiteral("verify"), pty.devicePath(), QStringLiteral("--duration"),
                                     QStringLiteral("10"), QStringLiteral("--baud"), QStringLiteral("115200"),
                                     QStringLiteral("--json")},
                                    60000);
        QVERIFY2(r.code == 2, qPrintable(r.out + r.err));
        const QJsonObject j = r.json();
        QVERIFY2(j.value(QLatin1String("still_intervals")).toInt() >= 1, qPrintable(r.out));
        const QJsonArray bias = j.value(QLatin1String("gyro_bias_dps")).toArray();
        const sim::SensorModel truth(63);
        QCOMPARE(bias.size(), 3);
        for (int a = 0; a < 3; ++a)
            QVERIFY2(std::fabs(bias[a].toDouble() - truth.gyroBias()[a]) < 0.02, qPrintable(r.out));
        QVERIFY(r.err.contains(QLatin1String("hold the module still for 3 s")));
    }

    // A compass (the simulated HEC495 on a pseudo-terminal, turned to the marks of a level
    // rose) whose heading is 10° off: the stops are matched to the bearings and the offset found.
    void compassAgainstBearings()
    {
        sim::Hec495Options o;
        o.motion = sim::Motion::Bearings;
        o.calibrated = true;
        o.headingBiasDeg = 10;
        sim::PtySimulator pty(std::make_unique<sim::Hec495Simulator>(o));
        QString error;
        QVERIFY2(pty.start(&error), qPrintable(error));
        const auto r = test::runCli({QStringLiteral("verify"), pty.devicePath(), QStringLiteral("--bearings"),
                                     QStringLiteral("45,90,135"), QStringLiteral("--duration"), QStringLiteral("18"),
                                     QStringLiteral("--baud"), QStringLiteral("9600"), QStringLiteral("--json")},
                                    60000);
        QVERIFY2(r.code == 1, qPrintable(r.out + r.err));
        const QJsonObject j = r.json();
        QCOMPARE(j.value(QLatin1String("bearings_held")).toInt(), 3);
        QCOMPARE(j.value(QLatin1String("verdict")).toString(), QStringLiteral("fail"));
        QVERIFY2(std::fabs(j.value(QLatin1String("heading_offset_deg")).toDouble() - 10) < 4, qPrintable(r.out));
        QVERIFY(j.value(QLatin1String("tilt_error_deg")).toObject().contains(QLatin1String("pitch")));
    }

    void badArguments()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("x.csv"));
        QVERIFY(motion_csv::write(csv, motion_csv::Motion::Still, 5));
        auto r = test::runCli({QStringLiteral("verify"), csv, QStringLiteral("--gravity"), QStringLiteral("5")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QLatin1String("--gravity needs m/s^2 between 9.7 and 9.9")));
        r = test::runCli({QStringLiteral("verify"), csv, QStringLiteral("--limit"), QStringLiteral("nonsense=1/2")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QLatin1String("heading_deg")));
        r = test::runCli({QStringLiteral("verify"), dir.filePath(QStringLiteral("missing.imucap"))});
        QCOMPARE(r.code, 1);
        QVERIFY(!r.err.isEmpty());
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliVerify)
#include "tst_cli_verify.moc"
