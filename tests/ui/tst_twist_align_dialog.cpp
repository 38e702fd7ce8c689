// TwistAlignDialog offscreen, on a session folder written here without hardware: three HI91
// captures (A 200 Hz, B 250 Hz at another sampling phase, C 100 Hz) of modules on one fixture
// that is turned sharply six times at irregular intervals. B's frames arrive 7.5 ms later
// than A's for the same motion, so B's common times are 7.5 ms late and its offset is -7.5 ms;
// C's module stood still (nothing to align: refused). The dialog finds B's offset within
// 0.2 ms with either reference, shows it in the table and the plot, stores it in session.json
// (C's earlier offset left as it was), reports a folder that is not a session, a garbled
// session.json and a missing capture, cancels a long search, and fits its window.
#include "../common/layout_checks.h"
#include "../common/test_main.h"
#include "../common/try_bounds.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "capture/capture_format.h"
#include "record/session_manifest.h"
#include "recording/twist_align_dialog.h"

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSplitter>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace imudesk;
using ui::CorrelationPlot;
using ui::TwistAlignDialog;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int64_t kStartNs = 20'000'000'000;   // the session's start on the host clock
constexpr int64_t kDelayNs = 2'000'000;        // every frame's arrival after its sampling instant
constexpr double kShiftBNs = 7'500'000;        // B's frames arrive this much later again
constexpr double kTruthBNs = -kShiftBNs;       // so B's offset (added to B's times) is this

// One sharp turn of the fixture: |rate| a raised cosine from zero to zero over widthS.
struct Twist {
    double atS, peakDps, widthS;
    double axis[3];
};

const std::vector<Twist> &twists()
{
    static const std::vector<Twist> t = {
        {2.00, 260, 0.20, {0, 0, 1}},   {3.35, 220, 0.20, {1, 0.2, 0}}, {5.90, 300, 0.22, {0.3, 1, 0.4}},
        {7.05, 240, 0.18, {0, 0.5, 1}}, {9.80, 280, 0.20, {1, 1, 0}},   {11.45, 210, 0.24, {0.2, 0, 1}},
    };
    return t;
}

// The fixture's angular rate (deg/s, fixture axes) at tS since the start.
void rate(double tS, double w[3])
{
    w[0] = w[1] = w[2] = 0;
    for (const Twist &k : twists()) {
        if (std::abs(tS - k.atS) >= k.widthS / 2)
            continue;
        const double s = k.peakDps * 0.5 * (1 + std::cos(2 * kPi * (tS - k.atS) / k.widthS));
        const double n = std::sqrt(k.axis[0] * k.axis[0] + k.axis[1] * k.axis[1] + k.axis[2] * k.axis[2]);
        for (int i = 0; i < 3; ++i)
            w[i] += s * k.axis[i] / n;
    }
}

struct DeviceSpec {
    QString name, file;
    double rateHz = 200;
    double phaseS = 0;        // first sample's instant after the start
    int64_t extraDelayNs = 0; // arrival later than A's for the same instant
    uint32_t counterStartMs = 0;
    bool still = false;       // the module is not on the turned fixture
    int mount = 0;            // 0: as the fixture; 1: axes permuted (x<-y, y<-z, z<-x)
    uint32_t seed = 1;
};

// One HI91 capture: each frame in a chunk of its own, arriving kDelayNs (+ extraDelayNs) after
// its sampling instant; its counter in whole ms (the rates divide 1000). Returns the frames.
quint64 writeCapture(const QString &path, const DeviceSpec &d, double durationS)
{
    namespace hp = protocol::hipnuc;
    namespace cap = capture;
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return 0;
    capture::CaptureHeader header;
    header.set(capture::CaptureHeader::kProduct, "HI14R3");
    header.set(capture::CaptureHeader::kBaud, "921600");
    auto bytes = cap::encodeFileHeader(header);
    f.write(reinterpret_cast<const char *>(bytes.data()), qint64(bytes.size()));
    std::mt19937 rng(d.seed);
    std::normal_distribution<double> noise(0, 0.3);
    std::vector<uint8_t> out;
    const int periodMs = int(std::lround(1000 / d.rateHz));
    quint64 frames = 0;
    for (uint64_t i = 0;; ++i) {
        const double tS = d.phaseS + double(i) * periodMs / 1000.0;
        if (tS > durationS)
            break;
        double w[3] = {0, 0, 0};
        if (!d.still)
            rate(tS, w);
        if (d.mount == 1)
            std::rotate(w, w + 1, w + 3);
        hp::Hi91 h;
        h.mainStatus = 0x1508;
        h.temperature = 25;
        h.pressure = 100676.f;
        h.systemTime = d.counterStartMs + uint32_t(i) * uint32_t(periodMs);
        h.acc = {0.f, 0.f, 1.f};
        h.gyr = {float(w[0] + 0.2 + noise(rng)), float(w[1] - 0.15 + noise(rng)), float(w[2] + 0.1 + noise(rng))};
        h.mag = {20.f, -5.f, 40.f};
        h.quat = {1.f, 0.f, 0.f, 0.f};
        const auto frame = hp::buildFrame(hp::encode(h));
        const int64_t hostNs = kStartNs + int64_t(std::llround(tS * 1e9)) + kDelayNs + d.extraDelayNs;
        cap::appendChunk(out, cap::ChunkReceived, hostNs, 1'700'000'000'000'000 + hostNs / 1000, frame.data(),
                         frame.size());
        ++frames;
        if (out.size() > (1u << 20)) {
            f.write(reinterpret_cast<const char *>(out.data()), qint64(out.size()));
            out.clear();
        }
    }
    f.write(reinterpret_cast<const char *>(out.data()), qint64(out.size()));
    return frames;
}

// The session: A, B (7.5 ms late, other rate, phase, counter and mounting) and C (still, with
// an offset stored earlier by hand).
bool writeSession(const QString &folder, double durationS = 14)
{
    if (!QDir().mkpath(folder))
        return false;
    const std::vector<DeviceSpec> specs = {
        {QStringLiteral("A"), QStringLiteral("01-A.imucap"), 200, 0.0, 0, 1000, false, 0, 1},
        {QStringLiteral("B"), QStringLiteral("02-B.imucap"), 250, 0.0013, int64_t(kShiftBNs), 777000, false, 1, 2},
        {QStringLiteral("C"), QStringLiteral("03-C.imucap"), 100, 0.0047, 0, 5, true, 0, 3},
    };
    record::SessionManifest m;
    m.startedUtc = QStringLiteral("2026-11-29T19:30:00.000Z");
    m.startedHostNs = kStartNs;
    m.stoppedHostNs = kStartNs + int64_t(durationS * 1e9) + 50'000'000;
    for (const DeviceSpec &s : specs) {
        record::SessionManifest::Device d;
        d.name = s.name;
        d.file = s.file;
        d.address = QStringLiteral("/dev/ttyUSB%1").arg(int(m.devices.size()));
        d.linkKind = QStringLiteral("HiPNUC serial");
        d.product = QStringLiteral("HI14R3");
        d.frames = writeCapture(QDir(folder).filePath(s.file), s, durationS);
        if (d.frames == 0)
            return false;
        d.bytes = quint64(QFileInfo(QDir(folder).filePath(s.file)).size());
        if (s.name == QLatin1String("C")) {
            d.offsetNs = 42e6;
            d.offsetMethod = QStringLiteral("manual");
        }
        m.devices.push_back(d);
    }
    QString error;
    return m.save(folder, &error);
}

int rowOf(const QTableWidget *t, const QString &device)
{
    for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, 0) && t->item(r, 0)->text() == device)
            return r;
    return -1;
}

// Pixels of the image within a small distance of `c`.
int pixelsLike(const QImage &img, const QColor &c)
{
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QColor p = img.pixelColor(x, y);
            if (std::abs(p.red() - c.red()) + std::abs(p.green() - c.green()) + std::abs(p.blue() - c.blue()) < 40)
                ++n;
        }
    return n;
}

// Runs the dialog's search and waits for it (generously: the machine may be busy).
bool search(TwistAlignDialog &d, bool *anyAligned)
{
    QSignalSpy finished(&d, &TwistAlignDialog::alignmentFinished);
    d.findOffsets();
    const bool ended = imudesk::test::waitFor([&] { return finished.count() > 0; }, 60000);
    if (ended)
        *anyAligned = finished.at(0).at(0).toBool();
    return ended && !d.isRunning();
}

} // namespace

class TstTwistAlignDialog : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(writeSession(m_dir.filePath(QStringLiteral("session"))));
    }

    void findsTheOffset_data()
    {
        QTest::addColumn<QString>("reference");
        QTest::addColumn<QString>("other");
        QTest::addColumn<double>("truthNs");
        QTest::newRow("first with gyro (A)") << QString() << "B" << kTruthBNs;
        QTest::newRow("B") << "B" << "A" << -kTruthBNs;
    }
    void findsTheOffset()
    {
        QFETCH(QString, reference);
        QFETCH(QString, other);
        QFETCH(double, truthNs);
        TwistAlignDialog d(m_dir.filePath(QStringLiteral("session")));
        auto *combo = d.findChild<QComboBox *>(QStringLiteral("reference"));
        QCOMPARE(combo->count(), 4); // automatic, A, B, C
        QVERIFY(d.setReferenceDevice(reference));
        QVERIFY(!d.setReferenceDevice(QStringLiteral("no such device")));
        QVERIFY(!d.findChild<QPushButton *>(QStringLiteral("store"))->isEnabled());

        QSignalSpy finished(&d, &TwistAlignDialog::alignmentFinished);
        QTest::mouseClick(d.findChild<QPushButton *>(QStringLiteral("find")), Qt::LeftButton);
        QVERIFY(d.isRunning()); // off the GUI thread: the click returned before the search ended
        QVERIFY(!d.findChild<QPushButton *>(QStringLiteral("find"))->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 60000);
        QVERIFY(!d.isRunning());
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(d.statusText()));
        QCOMPARE(d.findChild<QProgressBar *>(QStringLiteral("progress"))->value(), 1000);

        const auto results = d.results();
        QCOMPARE(int(results.size()), 3);
        const QString refName = reference.isEmpty() ? QStringLiteral("A") : reference;
        int otherIndex = -1, refIndex = -1;
        for (int i = 0; i < 3; ++i) {
            if (results[size_t(i)].name == other)
                otherIndex = i;
            if (results[size_t(i)].reference)
                refIndex = i;
        }
        QVERIFY(refIndex >= 0 && otherIndex >= 0);
        QCOMPARE(results[size_t(refIndex)].name, refName);
        const auto &r = results[size_t(otherIndex)];
        QVERIFY2(r.aligned(), r.result.whyNot.c_str());
        const double errorNs = r.result.offsetNs - truthNs;
        qInfo("%s against %s: offset %.4f ms (truth %.4f ms), error %.4f ms, +- %.4f ms, correlation %.5f",
              qPrintable(other), qPrintable(refName), r.result.offsetNs / 1e6, truthNs / 1e6, errorNs / 1e6,
              r.result.uncertaintyNs / 1e6, r.result.correlation);
        QVERIFY2(std::abs(errorNs) < 0.2e6, qPrintable(QString::number(errorNs / 1e6)));
        QVERIFY(r.result.correlation > 0.95);
        QVERIFY(r.result.twistsOther >= 4 && r.result.twistsReference >= 4);
        // C stood still: refused, with the reason.
        const auto &c = results[2];
        QVERIFY(!c.aligned());
        QVERIFY(!c.result.whyNot.empty());

        // The table shows them.
        auto *table = d.findChild<QTableWidget *>(QStringLiteral("results"));
        QCOMPARE(table->rowCount(), 3);
        const int row = rowOf(table, other);
        QVERIFY(row >= 0);
        bool ok = false;
        const double shownMs = table->item(row, 1)->text().toDouble(&ok);
        QVERIFY2(ok, qPrintable(table->item(row, 1)->text()));
        QVERIFY(std::abs(shownMs - truthNs / 1e6) < 0.2);
        QCOMPARE(table->item(row, 5)->text(), QStringLiteral("aligned"));
        QCOMPARE(table->item(rowOf(table, refName), 5)->text(), QStringLiteral("reference"));
        QVERIFY2(table->item(rowOf(table, QStringLiteral("C")), 5)->text().startsWith(QStringLiteral("Not aligned: ")),
                 qPrintable(table->item(rowOf(table, QStringLiteral("C")), 5)->text()));
        QVERIFY(d.findChild<QPushButton *>(QStringLiteral("store"))->isEnabled());

        // The plot has the aligned device's curve with its marker at the offset.
        const auto &curves = d.plot()->curves();
        QVERIFY(!curves.empty());
        QCOMPARE(curves.front().name, other);
        QVERIFY(curves.front().aligned);
        QVERIFY(std::abs(curves.front().offsetMs - truthNs / 1e6) < 0.2);
        QVERIFY(curves.front().points.size() > 100);
    }

    void storesTheOffsets()
    {
        const QString folder = m_dir.filePath(QStringLiteral("store"));
        QVERIFY(writeSession(folder));
        TwistAlignDialog d(folder);
        bool any = false;
        QVERIFY(search(d, &any));
        QVERIFY2(any, qPrintable(d.statusText()));
        const double found = d.results()[1].result.offsetNs;
        QSignalSpy stored(&d, &TwistAlignDialog::offsetsStored);
        QTest::mouseClick(d.findChild<QPushButton *>(QStringLiteral("store")), Qt::LeftButton);
        QCOMPARE(stored.count(), 1);
        QVERIFY2(stored.at(0).at(0).toBool(), qPrintable(stored.at(0).at(1).toString()));
        QVERIFY(d.statusText().contains(QStringLiteral("session.json")));

        record::SessionManifest m;
        QString error;
        QVERIFY2(record::SessionManifest::load(folder, &m, &error), qPrintable(error));
        QCOMPARE(int(m.devices.size()), 3);
        QCOMPARE(m.devices[0].offsetNs, 0.0);
        QCOMPARE(m.devices[0].offsetMethod, QStringLiteral("twist reference"));
        QVERIFY2(std::abs(m.devices[1].offsetNs - found) < 1, qPrintable(QString::number(m.devices[1].offsetNs)));
        QVERIFY(std::abs(m.devices[1].offsetNs - kTruthBNs) < 0.2e6);
        QCOMPARE(m.devices[1].offsetMethod, QStringLiteral("twist"));
        QCOMPARE(m.devices[2].offsetNs, 42e6); // not aligned: left as it was
        QCOMPARE(m.devices[2].offsetMethod, QStringLiteral("manual"));
        // The captures themselves are untouched: the next search finds the same offset.
        QVERIFY(search(d, &any));
        QVERIFY(std::abs(d.results()[1].result.offsetNs - found) < 1);
    }

    void refusesWhatIsNotASession()
    {
        QTemporaryDir empty;
        TwistAlignDialog d(empty.path());
        auto *status = d.findChild<QLabel *>(QStringLiteral("status"));
        QVERIFY2(status->text().contains(QStringLiteral("session.json")), qPrintable(status->text()));
        QVERIFY(status->property("error").toBool());
        QSignalSpy finished(&d, &TwistAlignDialog::alignmentFinished);
        d.findOffsets();
        QCOMPARE(finished.count(), 1); // said at once: nothing to read
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QVERIFY(!d.isRunning());
        QVERIFY(d.results().empty());
        QVERIFY(!d.findChild<QPushButton *>(QStringLiteral("store"))->isEnabled());
        QVERIFY(!d.storeOffsets());
        QVERIFY(!QFile::exists(QDir(empty.path()).filePath(QStringLiteral("session.json"))));

        // A session.json that is not one.
        QFile bad(QDir(empty.path()).filePath(QStringLiteral("session.json")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\"format\": \"something else\"}");
        bad.close();
        d.setSessionFolder(empty.path());
        QVERIFY2(status->text().contains(QStringLiteral("cannot be read")), qPrintable(status->text()));
        QCOMPARE(d.findChild<QComboBox *>(QStringLiteral("reference"))->count(), 1);

        // A folder that does not exist.
        d.setSessionFolder(QDir(empty.path()).filePath(QStringLiteral("missing")));
        QVERIFY2(status->text().contains(QStringLiteral("not a folder")), qPrintable(status->text()));
    }

    void reportsAMissingCapture()
    {
        const QString folder = m_dir.filePath(QStringLiteral("missing-capture"));
        QVERIFY(writeSession(folder));
        QVERIFY(QFile::remove(QDir(folder).filePath(QStringLiteral("02-B.imucap"))));
        TwistAlignDialog d(folder);
        bool any = true;
        QVERIFY(search(d, &any));
        QVERIFY(!any); // A is left with C, which stood still
        QVERIFY(!d.results()[1].error.isEmpty());
        auto *table = d.findChild<QTableWidget *>(QStringLiteral("results"));
        QVERIFY2(table->item(1, 5)->text().startsWith(QStringLiteral("Capture unreadable")),
                 qPrintable(table->item(1, 5)->text()));
        QVERIFY2(d.statusText().contains(QStringLiteral("could not be read")), qPrintable(d.statusText()));
        QVERIFY(!d.findChild<QPushButton *>(QStringLiteral("store"))->isEnabled());
        QVERIFY(!d.storeOffsets());
    }

    void refusesAnEmptyWindow()
    {
        TwistAlignDialog d(m_dir.filePath(QStringLiteral("session")));
        d.setWindow(5, 3);
        QSignalSpy finished(&d, &TwistAlignDialog::alignmentFinished);
        d.findOffsets();
        QCOMPARE(finished.count(), 1);
        QVERIFY(!d.isRunning());
        QVERIFY2(d.statusText().contains(QStringLiteral("later than")), qPrintable(d.statusText()));
        // A window around the twists is enough.
        d.setWindow(1, 13);
        bool any = false;
        QVERIFY(search(d, &any));
        QVERIFY2(any, qPrintable(d.statusText()));
        QVERIFY(std::abs(d.results()[1].result.offsetNs - kTruthBNs) < 0.2e6);
        // One without them is refused with the reason.
        d.setWindow(12.5, 13.9);
        QVERIFY(search(d, &any));
        QVERIFY(!any);
        QVERIFY2(!d.results()[1].result.whyNot.empty(), qPrintable(d.statusText()));
    }

    void plotRenders()
    {
        // Rendered on its own at a fixed size (the dialog's layout would resize its own plot
        // while it renders), with what the dialog's plot shows after a search.
        CorrelationPlot plot;
        plot.resize(640, 260);
        QImage empty(plot.size(), QImage::Format_ARGB32);
        empty.fill(Qt::magenta);
        plot.render(&empty);
        QCOMPARE(pixelsLike(empty, Qt::magenta), 0); // painted everywhere
        QCOMPARE(pixelsLike(empty, CorrelationPlot::curveColour(0)), 0);
        const QColor background = plot.palette().color(QPalette::Base);
        const int emptyBackground = pixelsLike(empty, background);
        QVERIFY(emptyBackground > 640 * 260 / 2);

        TwistAlignDialog d(m_dir.filePath(QStringLiteral("session")));
        bool any = false;
        QVERIFY(search(d, &any));
        QVERIFY(any);
        QVERIFY(!d.plot()->grab().isNull());
        plot.setCurves(d.plot()->curves());
        QImage img(plot.size(), QImage::Format_ARGB32);
        img.fill(Qt::magenta);
        plot.render(&img);
        QCOMPARE(pixelsLike(img, Qt::magenta), 0);
        const int curvePixels = pixelsLike(img, CorrelationPlot::curveColour(0));
        QVERIFY2(curvePixels > 300, qPrintable(QString::number(curvePixels)));
        QVERIFY(pixelsLike(img, background) < emptyBackground);
    }

    void cancelStopsALongSearch()
    {
        const QString folder = m_dir.filePath(QStringLiteral("long"));
        QVERIFY(writeSession(folder, 500));
        TwistAlignDialog d(folder);
        d.show();
        QSignalSpy finished(&d, &TwistAlignDialog::alignmentFinished);
        d.findOffsets();
        QVERIFY(d.isRunning());
        auto *cancel = d.findChild<QPushButton *>(QStringLiteral("cancel"));
        QCOMPARE(cancel->text(), QStringLiteral("Cancel"));
        QTest::mouseClick(cancel, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 60000);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QVERIFY(d.results().empty());
        QVERIFY2(d.statusText().contains(QStringLiteral("cancelled")), qPrintable(d.statusText()));
        QCOMPARE(cancel->text(), QStringLiteral("Close"));
        QVERIFY(d.isVisible()); // Cancel stopped the search, not the dialog
        QVERIFY(d.findChild<QPushButton *>(QStringLiteral("find"))->isEnabled());
    }

    void fitsItsWindow()
    {
        TwistAlignDialog d(m_dir.filePath(QStringLiteral("session")));
        bool any = false;
        QVERIFY(search(d, &any));
        QVERIFY(d.minimumSizeHint().width() <= 1366 && d.minimumSizeHint().height() <= 700);
        for (const QSize size : {QSize(900, 640), QSize(760, 540)}) {
            d.resize(size);
            d.show();
            QVERIFY(QTest::qWaitForWindowExposed(&d));
            QVERIFY(test::layout::layoutSettled(d));
            const QStringList problems = test::layout::cutOrOutside(d);
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
            QVERIFY(d.findChild<QTableWidget *>(QStringLiteral("results"))->height() >= 80);
            QVERIFY(d.plot()->height() >= 120);
        }
    }
};

IMUDESK_TEST_MAIN(TstTwistAlignDialog)
#include "tst_twist_align_dialog.moc"
