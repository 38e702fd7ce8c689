// imudesk-cli analyze: statistics, output rate and jitter, frames lost and Allan deviation of
// a capture file or of a CSV written by the vendor's PC tool.
#include "cli_context.h"
#include "record/file_analysis.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>

namespace imudesk::cli {

namespace {

QJsonObject resultJson(const record::SampleAnalyzer::Result &r)
{
    QJsonObject o;
    o[QStringLiteral("source")] = QString::fromStdString(r.source);
    o[QStringLiteral("frames")] = double(r.frames);
    o[QStringLiteral("duration_s")] = r.durationS;
    o[QStringLiteral("rate_hz")] = r.rateHz;
    o[QStringLiteral("interval_ms")] = QJsonObject{{QStringLiteral("mean"), r.intervalMeanMs},
                                                   {QStringLiteral("std"), r.intervalStdMs},
                                                   {QStringLiteral("min"), r.intervalMinMs},
                                                   {QStringLiteral("max"), r.intervalMaxMs}};
    QJsonArray hist;
    for (const auto &b : r.intervals)
        hist.append(QJsonObject{{QStringLiteral("from_ms"), b.fromMs},
                                {QStringLiteral("to_ms"), std::isfinite(b.toMs) ? QJsonValue(b.toMs) : QJsonValue()},
                                {QStringLiteral("count"), double(b.count)}});
    o[QStringLiteral("interval_histogram")] = hist;
    o[QStringLiteral("frames_lost")] = double(r.framesLost);
    o[QStringLiteral("device_resets")] = double(r.deviceResets);
    QJsonObject channels;
    for (const auto &c : r.channels)
        channels[QString::fromStdString(c.name)] =
            QJsonObject{{QStringLiteral("unit"), QString::fromStdString(c.unit)}, {QStringLiteral("mean"), c.mean},
                        {QStringLiteral("std"), c.std}, {QStringLiteral("min"), c.min}, {QStringLiteral("max"), c.max}};
    o[QStringLiteral("channels")] = channels;
    QJsonObject allan;
    for (const auto &a : r.axes) {
        QJsonArray tau, adev;
        for (const auto &p : a.curve) {
            tau.append(p.tau);
            adev.append(p.adev);
        }
        QJsonObject ax{{QStringLiteral("unit"), QString::fromStdString(a.unit)},
                       {QStringLiteral("tau_s"), tau},
                       {QStringLiteral("adev"), adev}};
        if (a.summary.haveOneSecond)
            ax[QStringLiteral("random_walk")] = a.summary.atOneSecond; // unit * sqrt(s)
        if (a.summary.haveMinimum) {
            ax[QStringLiteral("bias_instability")] = a.summary.biasInstability;
            ax[QStringLiteral("bias_instability_tau_s")] = a.summary.minimumTau;
        }
        allan[QString::fromStdString(a.name)] = ax;
    }
    // A module that moved or a recording too short: no Allan figures (null), and why.
    o[QStringLiteral("allan")] = r.allanJudged() ? QJsonValue(allan) : QJsonValue();
    o[QStringLiteral("moved")] = r.motion.moved;
    o[QStringLiteral("too_short")] = r.allanWhyNot == record::SampleAnalyzer::AllanWhyNot::TooShort;
    if (!r.allanJudged()) {
        o[QStringLiteral("allan_reason")] = r.allanReason();
        o[QStringLiteral("allan_reason_detail")] = r.allanDetail();
    }
    o[QStringLiteral("motion")] = QJsonObject{{QStringLiteral("gyro_std_dps"), r.motion.gyroStdDps},
                                              {QStringLiteral("window_rate_change_dps"), r.motion.rateChangeDps},
                                              {QStringLiteral("window_acc_change_g"), r.motion.accChangeG},
                                              {QStringLiteral("mean_rate_dps"), r.motion.meanRateDps}};
    o[QStringLiteral("tau_max_s")] = r.tauMax;
    o[QStringLiteral("recommended_length_s")] = r.recommendedLengthS;
    return o;
}

void printText(const record::SampleAnalyzer::Result &r)
{
    std::printf("source: %s, %llu frames, %.3f s of device time\n", r.source.c_str(),
                static_cast<unsigned long long>(r.frames), r.durationS);
    std::printf("output rate: %.3f Hz; interval mean %.4f ms, std %.4f ms, min %.3f ms, max %.3f ms\n", r.rateHz,
                r.intervalMeanMs, r.intervalStdMs, r.intervalMinMs, r.intervalMaxMs);
    std::printf("frames lost (system_time gaps): %llu, device resets: %llu\n",
                static_cast<unsigned long long>(r.framesLost), static_cast<unsigned long long>(r.deviceResets));
    std::printf("interval histogram:\n");
    for (const auto &b : r.intervals)
        if (b.count)
            std::printf("  %8.3f - %8.3f ms  %llu\n", b.fromMs, b.toMs, static_cast<unsigned long long>(b.count));
    std::printf("%-12s %-6s %14s %14s %14s %14s\n", "channel", "unit", "mean", "std", "min", "max");
    for (const auto &c : r.channels)
        std::printf("%-12s %-6s %14.6g %14.6g %14.6g %14.6g\n", c.name.c_str(), c.unit.c_str(), c.mean, c.std, c.min,
                    c.max);
    if (!r.allanJudged()) {
        // Not the sensor's noise, or too little of it: no Allan deviation, random walk or bias
        // instability.
        std::printf("Allan deviation: %s (%s)\n", qPrintable(r.allanReason()), qPrintable(r.allanDetail()));
    } else {
        std::printf("Allan deviation (overlapping):\n");
    }
    for (const auto &a : r.axes) {
        const bool gyro = a.unit == "deg/s";
        std::printf("  %s:", a.name.c_str());
        if (a.summary.flat)
            std::printf(" no noise to measure: its values never change (below the file's resolution, or a constant column)");
        if (a.summary.haveOneSecond) {
            if (gyro)
                std::printf(" ARW %.4g deg/sqrt(h)", a.summary.atOneSecond * 60.0);
            else
                std::printf(" VRW %.4g m/s/sqrt(h)", a.summary.atOneSecond * model::kGravity * 60.0);
        }
        if (a.summary.haveMinimum) {
            if (gyro)
                std::printf(", bias instability %.4g deg/h at tau %.3g s", a.summary.biasInstability * 3600.0,
                            a.summary.minimumTau);
            else
                std::printf(", bias instability %.4g mG at tau %.3g s", a.summary.biasInstability * 1000.0,
                            a.summary.minimumTau);
        }
        std::printf("\n");
    }
    std::printf("recommended minimum recording length for tau up to %.0f s: %.0f s (%.1f h), for 10 %% uncertainty\n",
                r.tauMax, r.recommendedLengthS, r.recommendedLengthS / 3600.0);
}

} // namespace

int cmdAnalyze(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("Machine-readable JSON output.")));
    p.addOption(QCommandLineOption(QStringLiteral("tau-max"),
                                   QStringLiteral("Longest Allan cluster time of interest, s (default 1000)."),
                                   QStringLiteral("S"), QStringLiteral("1000")));
    p.addOption(QCommandLineOption(QStringLiteral("type"), QStringLiteral("Frame type to analyse (default: the first "
                                                                          "with gyro data)."),
                                   QStringLiteral("HI91")));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Capture file (.imucap) or vendor HI91 CSV."));
    if (!parseArgs(p, args, QStringLiteral("imudesk-cli analyze FILE [--json] [--tau-max S] [--type HI91]")))
        return ExitUsage;
    if (p.positionalArguments().size() != 1)
        return fail(QStringLiteral("analyze needs exactly one FILE"), ExitUsage);
    bool ok = false;
    const double tauMax = p.value(QStringLiteral("tau-max")).toDouble(&ok);
    if (!ok || tauMax <= 0)
        return fail(QStringLiteral("--tau-max needs a positive number of seconds"), ExitUsage);
    const QString path = p.positionalArguments().front();
    const auto outcome = record::FileAnalysis::run(path, p.value(QStringLiteral("type")).toStdString(), tauMax,
                                                   [](double) { return !interrupted(); });
    for (const QString &w : outcome.warnings)
        std::fprintf(stderr, "imudesk-cli: warning: %s\n", qPrintable(w));
    if (!outcome.ok)
        return fail(outcome.error, outcome.cancelled ? ExitInterrupted : ExitFailure);
    const auto &result = outcome.result;
    if (p.isSet(QStringLiteral("json")))
        out(QString::fromUtf8(QJsonDocument(resultJson(result)).toJson(QJsonDocument::Compact)));
    else
        printText(result);
    std::fflush(stdout);
    return ExitOk;
}

} // namespace imudesk::cli
