// The magnetometer sphere view (offscreen): fed with the simulated module's magnetometer
// while it tumbles (HI91 frames decoded in process), the covered cells grow, the hint of
// the missing rotation goes away when everything is covered, and the picture shows green
// cells; with the fitted calibration the corrected samples cover the sphere; a finished run
// keeps all its samples and is read out from its result.
#include "calib/mag_calibrator.h"
#include "calibration/mag_sphere_view.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/stream/stream_demux.h"
#include "sim/hipnuc_simulator.h"
#include "../common/test_main.h"

#include <QImage>
#include <QTest>

using namespace imudesk;
using Eigen::Vector3d;

namespace {

std::vector<Vector3d> simulatedMag(sim::Motion motion, double seconds)
{
    sim::SimOptions o;
    o.motion = motion;
    o.seed = 4;
    sim::HipnucSimulator dev(o);
    protocol::StreamDemux demux;
    std::vector<Vector3d> out;
    for (int64_t t = 0; t <= int64_t(seconds * 1e6); t += 100000) {
        dev.advanceTo(t);
        const auto bytes = dev.takeOutput();
        for (const auto &e : demux.feed(bytes.data(), bytes.size())) {
            protocol::hipnuc::Hi91 f;
            if (e.kind == protocol::StreamEvent::Kind::Frame && protocol::hipnuc::decodeHi91(e.payload.data(), e.payload.size(), f))
                out.emplace_back(f.mag[0], f.mag[1], f.mag[2]);
        }
    }
    return out;
}

int greenPixels(const QImage &img)
{
    int n = 0;
    for (int y = 0; y < img.height(); y += 2)
        for (int x = 0; x < img.width(); x += 2) {
            const QColor c = img.pixelColor(x, y);
            if (c.green() > c.red() + 40 && c.green() > c.blue() + 40)
                ++n;
        }
    return n;
}

} // namespace

class TstMagSphereView : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void coverageGrowsWhileTumbling()
    {
        ui::MagSphereView view;
        view.resize(400, 440);
        QCOMPARE(view.coveragePercent(), 0.0);
        QVERIFY(!view.hint().isEmpty());
        QCOMPARE(greenPixels(view.grab().toImage()), 0);

        const auto samples = simulatedMag(sim::Motion::Tumble, 120);
        QVERIFY(samples.size() > 5000);
        double before = 0;
        for (size_t i = 0; i < samples.size(); ++i) {
            view.addSample(samples[i]);
            if (i == 300) {
                before = view.coveragePercent();
                QVERIFY(before > 0 && before < 60);
                QVERIFY(view.hint().contains(QStringLiteral("axis")));
            }
        }
        QVERIFY(view.coveragePercent() > before);
        QVERIFY(view.sampleCount() <= ui::MagSphereView::kMaxSamples);
        QVERIFY(view.lastFieldUt() > 20);
        QVERIFY(greenPixels(view.grab().toImage()) > 200);

        // Our fit of the same samples; the corrected view is the "after" sphere.
        const calib::MagCalResult r = calib::MagCalibrator().calibrate(samples);
        QVERIFY2(r.usable(), qPrintable(r.reason));
        view.setCalibration(r.hardIron, r.softIron);
        QVERIFY(view.coveragePercent() >= 90);
        QVERIFY(std::fabs(view.lastFieldUt() - r.fieldUt) < 2);
        view.clear();
        QCOMPARE(view.sampleCount(), size_t(0));
    }

    // Issue 32 point 5: a finished run keeps every sample (the first 4000 before, so its cells
    // and count were not the run's) and is read out from its result: the coverage, sample
    // count and predicted heading error the result page and the report give, in µT terms,
    // without the instruction to turn that a live view shows.
    void finishedRunIsReadOutFromItsResult()
    {
        const auto mags = simulatedMag(sim::Motion::Tumble, 60);
        QVERIFY2(mags.size() > ui::MagSphereView::kMaxSamples, qPrintable(QString::number(mags.size())));
        const calib::MagCalResult fit = calib::MagCalibrator().calibrate(mags);
        QVERIFY2(fit.usable(), qPrintable(fit.reason));
        ui::MagSphereView view;
        view.resize(400, 440);
        view.setSamples(mags);
        view.setCalibration(fit.hardIron, fit.softIron);
        QCOMPARE(view.sampleCount(), mags.size());
        QCOMPARE(view.coveragePercent(), fit.coveragePct);
        view.showRun(fit);
        const QString readout = view.readoutText();
        QVERIFY2(readout.contains(QStringLiteral("%1 samples").arg(fit.samples)), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("coverage %1 %").arg(fit.coveragePct, 0, 'f', 0)), qPrintable(readout));
        QVERIFY2(readout.contains(QString::number(fit.predictedHeadingErrorDeg, 'f', 2) + QStringLiteral("°")),
                 qPrintable(readout));
        QVERIFY(!readout.contains(QStringLiteral("Turn the module")));
        QVERIFY(!readout.contains(QStringLiteral("uT")));
        // Live again after clear(): the live read-out, in µT.
        view.clear();
        view.clearCalibration();
        view.addSample(mags.front());
        QVERIFY(!view.showsRun());
        QVERIFY2(view.readoutText().contains(QStringLiteral("µT")), qPrintable(view.readoutText()));
    }

    void spinCoversOnlyABand()
    {
        ui::MagSphereView view;
        view.setSamples(simulatedMag(sim::Motion::Spin, 15));
        QVERIFY(view.coveragePercent() < 40);
        QVERIFY(!view.hint().isEmpty());
    }
};

IMUDESK_TEST_MAIN(TstMagSphereView)
#include "tst_mag_sphere_view.moc"
