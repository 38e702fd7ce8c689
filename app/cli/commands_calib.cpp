// imudesk-cli commands for calibration: magcal (the wizard's magnetometer fit on a file: any file
// ImuDesk writes or imports that carries a magnetometer, record/magnetometer_file.h).
#include "calib/mag_calibrator.h"
#include "cli_context.h"
#include "record/magnetometer_file.h"

#include <QDir>
#include <QJsonDocument>

#include <cmath>
#include <cstdio>

namespace imudesk::cli {

int cmdMagcal(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("Print the result as one JSON object.")));
    p.addOption(QCommandLineOption(QStringLiteral("mode"),
                                   QStringLiteral("full (default), hard_iron_only or planar."), QStringLiteral("MODE"),
                                   QStringLiteral("full")));
    p.addOption(QCommandLineOption(QStringLiteral("field"),
                                   QStringLiteral("Expected |B| in uT (world magnetic model); hard_iron_only holds it."),
                                   QStringLiteral("UT")));
    p.addOption(QCommandLineOption(QStringLiteral("inclination"),
                                   QStringLiteral("Field inclination in degrees (world magnetic model) for the predicted "
                                                  "heading error; default %1.")
                                       .arg(calib::MagFitUncertainty::kDefaultInclinationDeg),
                                   QStringLiteral("DEG")));
    p.addOption(QCommandLineOption(QStringLiteral("device"),
                                   QStringLiteral("The device of a recorded session (its folder or its export) to fit."),
                                   QStringLiteral("NAME")));
    p.addPositionalArgument(QStringLiteral("FILE"),
                            QStringLiteral("A capture (.imucap), a recorded session's folder, a vendor CSV, a tidy CSV "
                                           "or JSON Lines export, or a CSV with the columns mag_x,mag_y,mag_z (uT)."));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli magcal FILE [--json] [--mode full|hard_iron_only|planar] [--field UT] "
                                                 "[--inclination DEG] [--device NAME]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("magcal needs exactly one FILE"), ExitUsage);
    calib::MagCalMode mode;
    if (!calib::parseMode(p.value(QStringLiteral("mode")), mode))
        return fail(QStringLiteral("--mode must be full, hard_iron_only or planar, got '%1'").arg(p.value(QStringLiteral("mode"))),
                    ExitUsage);
    calib::MagCalibrator::Options options;
    if (p.isSet(QStringLiteral("field"))) {
        bool ok = false;
        options.referenceFieldUt = p.value(QStringLiteral("field")).toDouble(&ok);
        if (!ok || !(options.referenceFieldUt > 0) || options.referenceFieldUt > 1000)
            return fail(QStringLiteral("--field needs |B| in uT (0..1000), got '%1'").arg(p.value(QStringLiteral("field"))),
                        ExitUsage);
    }
    if (p.isSet(QStringLiteral("inclination"))) {
        bool ok = false;
        options.inclinationDeg = p.value(QStringLiteral("inclination")).toDouble(&ok);
        // At +-90 deg there is no horizontal field and no heading.
        if (!ok || !(std::fabs(options.inclinationDeg) <= 85))
            return fail(QStringLiteral("--inclination needs degrees in -85..85, got '%1'").arg(p.value(QStringLiteral("inclination"))),
                        ExitUsage);
    }

    const QString path = p.positionalArguments().front();
    const auto input = record::MagnetometerFile::read(path, p.value(QStringLiteral("device")));
    if (!input.ok)
        return fail(input.error);
    for (const QString &note : input.notes)
        std::fprintf(stderr, "imudesk-cli: note: %s\n", qPrintable(note));
    std::fprintf(stderr, "imudesk-cli: %s: %s%s, %zu magnetometer samples (%s)\n",
                 qPrintable(QDir::toNativeSeparators(path)), qPrintable(input.kind),
                 input.device.isEmpty() ? "" : qPrintable(QStringLiteral(", device ") + input.device),
                 input.samples.size(), qPrintable(input.source));
    const std::vector<Eigen::Vector3d> &samples = input.samples;

    const calib::MagCalResult r = calib::MagCalibrator(options).calibrate(samples, mode);
    if (p.isSet(QStringLiteral("json"))) {
        out(QString::fromUtf8(QJsonDocument(r.toJson()).toJson(QJsonDocument::Compact)));
    } else {
        out(QStringLiteral("verdict\t%1").arg(QLatin1String(calib::verdictName(r.verdict))));
        out(QStringLiteral("reason\t%1").arg(r.reason));
        out(QStringLiteral("mode\t%1").arg(QLatin1String(calib::modeName(r.mode))));
        out(QStringLiteral("samples\t%1 (%2 set aside)").arg(r.samples).arg(r.outliers));
        if (r.usable() || r.verdict == calib::MagVerdict::Fail) {
            out(QStringLiteral("hard_iron_ut\t%1 %2 %3").arg(r.hardIron.x(), 0, 'f', 3).arg(r.hardIron.y(), 0, 'f', 3).arg(r.hardIron.z(), 0, 'f', 3));
            for (int i = 0; i < 3; ++i)
                out(QStringLiteral("soft_iron_row%1\t%2 %3 %4")
                        .arg(i)
                        .arg(r.softIron(i, 0), 0, 'f', 6)
                        .arg(r.softIron(i, 1), 0, 'f', 6)
                        .arg(r.softIron(i, 2), 0, 'f', 6));
            out(QStringLiteral("field_ut\t%1").arg(r.fieldUt, 0, 'f', 3));
            out(QStringLiteral("fit_error_pct\t%1").arg(r.fitErrorPct, 0, 'f', 3));
            out(QStringLiteral("residual_rms_ut\t%1").arg(r.residualRmsUt, 0, 'f', 3));
        }
        // The accuracy the data can give; "unknown" when the fit did not get that far.
        auto figure = [](double v, int decimals) {
            return std::isfinite(v) ? QString::number(v, 'f', decimals)
                                    : std::isinf(v) ? QStringLiteral("unbounded") : QStringLiteral("unknown");
        };
        out(QStringLiteral("hard_iron_sigma_ut\t%1").arg(figure(r.hardIronSigmaUt, 3)));
        out(QStringLiteral("soft_iron_sigma_pct\t%1").arg(figure(r.softIronSigmaPct, 3)));
        out(QStringLiteral("predicted_heading_error_deg\t%1").arg(figure(r.predictedHeadingErrorDeg, 3)));
        out(QStringLiteral("predicted_heading_error_95_deg\t%1").arg(figure(r.predictedHeadingError95Deg, 3)));
        out(QStringLiteral("coverage_pct\t%1").arg(r.coveragePct, 0, 'f', 1));
        out(QStringLiteral("eigen_ratio\t%1").arg(r.eigenRatio, 0, 'f', 2));
    }
    // 0: a usable calibration (pass or warn); 1: fail or refused (the result is printed anyway).
    return r.usable() ? ExitOk : ExitFailure;
}

} // namespace imudesk::cli
