#include "calibration/calibration_report.h"

#include "calib/mag_cal_procedure.h"
#include "calib/mag_cal_result.h"
#include "calibration/mag_sphere_view.h"
#include "itemmodels/calibration_history_model.h"
#include "reports/pdf_output.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QPainter>
#include <QStringList>
#include <QTextDocument>

#include <cmath>
#include <set>

Q_LOGGING_CATEGORY(lcCalReport, "imudesk.ui.calreport")

namespace imudesk::ui {

namespace {

struct MetricSpec {
    const char *key;
    const char *label; // translated through CalibrationReport::tr
    int decimals;      // -1: text, integer or yes/no
};

// The known keys of the wizards' result JSON, with their units.
constexpr MetricSpec kSpecs[] = {
    // magnetometer (MagCalResult::toJson)
    {"mode", QT_TRANSLATE_NOOP("CalibrationReport", "Fit"), -1},
    {"field_ut", QT_TRANSLATE_NOOP("CalibrationReport", "Field strength |B| (µT)"), 2},
    {"hard_iron", QT_TRANSLATE_NOOP("CalibrationReport", "Hard iron x, y, z (µT)"), 2},
    {"soft_iron", QT_TRANSLATE_NOOP("CalibrationReport", "Soft-iron matrix (rows, unitless)"), 4},
    {"fit_error_pct", QT_TRANSLATE_NOOP("CalibrationReport", "Fit error (%)"), 2},
    {"residual_rms_ut", QT_TRANSLATE_NOOP("CalibrationReport", "Residual RMS (µT)"), 3},
    {"coverage_pct", QT_TRANSLATE_NOOP("CalibrationReport", "Sphere coverage (%)"), 0},
    {"predicted_heading_error_deg",
     QT_TRANSLATE_NOOP("CalibrationReport", "Predicted heading error, level module, 68 % bound (deg)"), 2},
    {"predicted_heading_error_95_deg",
     QT_TRANSLATE_NOOP("CalibrationReport", "Predicted heading error, level module, 95 % bound (deg)"), 2},
    {"hard_iron_sigma_ut", QT_TRANSLATE_NOOP("CalibrationReport", "Hard-iron uncertainty, RMS (µT)"), 3},
    {"soft_iron_sigma_pct", QT_TRANSLATE_NOOP("CalibrationReport", "Soft-iron uncertainty, RMS (%)"), 2},
    {"eigen_ratio", QT_TRANSLATE_NOOP("CalibrationReport", "Eigenvalue ratio (max/min)"), 2},
    {"samples", QT_TRANSLATE_NOOP("CalibrationReport", "Samples fitted"), -1},
    {"outliers", QT_TRANSLATE_NOOP("CalibrationReport", "Samples set aside as outliers"), -1},
    {"hard_iron_only_offered", QT_TRANSLATE_NOOP("CalibrationReport", "Hard-iron-only fit offered"), -1},
    {"planar_offered", QT_TRANSLATE_NOOP("CalibrationReport", "Planar (2-D) fit offered"), -1},
    {"z_offset_known", QT_TRANSLATE_NOOP("CalibrationReport", "Vertical offset known"), -1},
    // gyro scale factor (GyroScaleWizard::resultJson)
    {"target_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Target angle (deg)"), -1},
    {"device_ok", QT_TRANSLATE_NOOP("CalibrationReport", "Device accepted"), -1},
    {"device_reply", QT_TRANSLATE_NOOP("CalibrationReport", "Device reply"), -1},
    {"estimate_complete", QT_TRANSLATE_NOOP("CalibrationReport", "ImuDesk estimate available"), -1},
    {"scale_error_pct", QT_TRANSLATE_NOOP("CalibrationReport", "Scale error, ImuDesk estimate (%)"), 3},
    {"angle_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Angle turned (deg)"), 1},
    {"duration_s", QT_TRANSLATE_NOOP("CalibrationReport", "Duration (s)"), 1},
    {"mean_rate_dps", QT_TRANSLATE_NOOP("CalibrationReport", "Mean rate (deg/s)"), 1},
    {"in_band_pct", QT_TRANSLATE_NOOP("CalibrationReport", "Time in the 20-100 deg/s band (%)"), 0},
    {"uniformity_pct", QT_TRANSLATE_NOOP("CalibrationReport", "Rate unevenness, std/mean (%)"), 1},
    {"stopped_in_window", QT_TRANSLATE_NOOP("CalibrationReport", "Stopped within +-5 deg of the target"), -1},
    {"acceptable", QT_TRANSLATE_NOOP("CalibrationReport", "Run met the manual's conditions"), -1},
    {"bias_dps", QT_TRANSLATE_NOOP("CalibrationReport", "Gyro bias along the axis (deg/s)"), 3},
    {"axis_tilt_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Axis tilt from sensor z (deg)"), 2},
    {"odr_hz", QT_TRANSLATE_NOOP("CalibrationReport", "Output rate (Hz)"), 1},
    // attitude reset (AttitudeResetWizard::resultJson)
    {"variant", QT_TRANSLATE_NOOP("CalibrationReport", "Variant (ATT RST)"), -1},
    {"command", QT_TRANSLATE_NOOP("CalibrationReport", "Command sent"), -1},
    {"still_for_s", QT_TRANSLATE_NOOP("CalibrationReport", "Still for, when sent (s)"), 1},
    {"gyro_std_dps", QT_TRANSLATE_NOOP("CalibrationReport", "Gyro spread, when sent (deg/s)"), 4},
    {"acc_std_g", QT_TRANSLATE_NOOP("CalibrationReport", "Accelerometer spread, when sent (G)"), 5},
    {"roll_before_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Roll before (deg)"), 2},
    {"pitch_before_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Pitch before (deg)"), 2},
    {"roll_after_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Roll after (deg)"), 2},
    {"pitch_after_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Pitch after (deg)"), 2},
    {"yaw_after_deg", QT_TRANSLATE_NOOP("CalibrationReport", "Yaw after (deg)"), 2},
    // HEC495 compass (Hec495CalibrationWizard::resultJson)
    {"method", QT_TRANSLATE_NOOP("CalibrationReport", "Method"), -1},
    {"method_code", QT_TRANSLATE_NOOP("CalibrationReport", "Start command byte"), -1},
    {"fit_err", QT_TRANSLATE_NOOP("CalibrationReport", "FitErr (module's fit error)"), 2},
    {"max_good_fit_err", QT_TRANSLATE_NOOP("CalibrationReport", "FitErr limit (manual)"), 0},
    {"points", QT_TRANSLATE_NOOP("CalibrationReport", "Points used"), -1},
    {"valid_points", QT_TRANSLATE_NOOP("CalibrationReport", "Valid points collected"), -1},
};

QString valueText(const QJsonValue &v, int decimals)
{
    // A figure the run could not determine (null), or an unbounded one (written as 1e12).
    if (v.isNull())
        return CalibrationReport::tr("unknown");
    if (v.isDouble() && std::fabs(v.toDouble()) >= 1e12)
        return CalibrationReport::tr("unbounded");
    if (v.isBool())
        return v.toBool() ? CalibrationReport::tr("yes") : CalibrationReport::tr("no");
    if (v.isDouble()) {
        const double d = v.toDouble();
        if (decimals < 0)
            return d == std::floor(d) ? QString::number(qint64(d)) : QString::number(d, 'g', 6);
        return QString::number(d, 'f', decimals);
    }
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        QStringList parts;
        for (const QJsonValue &x : a)
            parts << (x.isArray() ? QLatin1Char('[') + valueText(x, decimals) + QLatin1Char(']') : valueText(x, decimals));
        return parts.join(QStringLiteral(", "));
    }
    return v.toString();
}

} // namespace

CalibrationReport::CalibrationReport(calib::CalibrationRecord record, calib::SampleTable samples)
    : m_record(std::move(record)),
      m_samples(std::move(samples)),
      m_document(std::make_unique<QTextDocument>())
{
    renderSphere();
    buildHtml();
}

CalibrationReport::~CalibrationReport() = default;

QUrl CalibrationReport::sphereUrl()
{
    return QUrl(QStringLiteral("imudesk-report://sphere.png"));
}

QString CalibrationReport::verdictText(const QString &verdict)
{
    calib::MagVerdict v;
    return calib::parseVerdict(verdict, v) ? calib::MagCalResult::verdictText(v) : verdict;
}

QList<QPair<QString, QString>> CalibrationReport::metrics(const calib::CalibrationRecord &record)
{
    QList<QPair<QString, QString>> out;
    // The device's own run is a section of its own (deviceSection), not a metric of the fit.
    std::set<QString> known{QStringLiteral("verdict"), QStringLiteral("reason"), QStringLiteral("device_calibration")};
    for (const MetricSpec &s : kSpecs) {
        const QString key = QLatin1String(s.key);
        known.insert(key);
        if (record.result.contains(key))
            out.append({tr(s.label), valueText(record.result.value(key), s.decimals)});
    }
    for (auto it = record.result.begin(); it != record.result.end(); ++it)
        if (!known.count(it.key()))
            out.append({it.key(), valueText(it.value(), -1)});
    return out;
}

std::vector<Eigen::Vector3d> CalibrationReport::magSamples(const calib::SampleTable &samples)
{
    std::vector<Eigen::Vector3d> out;
    const int x = samples.columnIndex(QStringLiteral("mag_x"));
    const int y = samples.columnIndex(QStringLiteral("mag_y"));
    const int z = samples.columnIndex(QStringLiteral("mag_z"));
    if (x < 0 || y < 0 || z < 0)
        return out;
    out.reserve(samples.rows.size());
    for (const auto &row : samples.rows) {
        const Eigen::Vector3d m(row[size_t(x)], row[size_t(y)], row[size_t(z)]);
        if (m.squaredNorm() > 0) // rows of runs that streamed no field carry zeros
            out.push_back(m);
    }
    return out;
}

void CalibrationReport::renderSphere()
{
    const std::vector<Eigen::Vector3d> mags = magSamples(m_samples);
    if (mags.empty())
        return;
    calib::MagCalResult fit;
    const bool known = m_record.kind == QLatin1String("magnetometer") && calib::MagCalResult::fromJson(m_record.result, fit);
    if (!known) {
        // No result to read the figures from: the picture still says what it shows, a count.
        fit = calib::MagCalResult();
        fit.samples = int(mags.size());
    }
    const bool corrected = known && fit.usable();
    const int panels = corrected ? 2 : 1;
    m_sphere = QImage(kSphereSize * panels, kSphereSize, QImage::Format_RGB32);
    m_sphere.fill(Qt::white);
    QPainter painter(&m_sphere);
    for (int i = 0; i < panels; ++i) {
        MagSphereView view;
        view.setAttribute(Qt::WA_DontShowOnScreen);
        view.resize(kSphereSize, kSphereSize);
        QPalette pal = view.palette();
        pal.setColor(QPalette::Base, Qt::white);
        pal.setColor(QPalette::Text, Qt::black);
        view.setPalette(pal);
        view.setSamples(mags);
        if (i == 1)
            view.setCalibration(fit.hardIron, fit.softIron);
        // A finished run: its figures under the sphere, and no instruction to turn.
        view.showRun(fit);
        view.render(&painter, QPoint(i * kSphereSize, 0));
    }
}

void CalibrationReport::buildHtml()
{
    const calib::CalibrationRecord &r = m_record;
    const QString verdict = r.verdict();
    const QString reason = r.result.value(QStringLiteral("reason")).toString();
    auto esc = [](const QString &s) { return s.toHtmlEscaped(); };
    const QString kind = models::CalibrationHistoryModel::kindText(r.kind);
    QString h;
    h += QStringLiteral("<html><body style=\"font-family: sans-serif;\">");
    h += QStringLiteral("<h1>%1</h1>").arg(esc(tr("ImuDesk calibration report: %1").arg(kind)));
    h += QStringLiteral("<table cellspacing=\"0\" cellpadding=\"3\">");
    auto row = [&h, &esc](const QString &label, const QString &value) {
        h += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(esc(label), esc(value));
    };
    row(tr("Device"), r.product.isEmpty() ? tr("unknown") : r.product);
    row(tr("Serial number"), r.deviceSerial.isEmpty() ? tr("unknown") : r.deviceSerial);
    row(tr("Firmware"), r.firmware.isEmpty() ? tr("unknown") : r.firmware);
    row(tr("Time (UTC)"), r.time.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")));
    row(tr("Calibration"), kind);
    row(tr("Samples recorded"), QString::number(r.sampleCount));
    h += QStringLiteral("</table>");

    const QString colour = verdict == QLatin1String("pass") ? QStringLiteral("#1b7f2a")
        : verdict == QLatin1String("warn")                  ? QStringLiteral("#a66300")
                                                            : QStringLiteral("#b00020");
    h += QStringLiteral("<h2>%1 <span style=\"color: %2;\">%3</span></h2>")
             .arg(esc(tr("Verdict:")), colour, esc(verdictText(verdict)));
    if (!reason.isEmpty())
        h += QStringLiteral("<p>%1</p>").arg(esc(reason));

    h += QStringLiteral("<h2>%1</h2>").arg(esc(tr("Metrics")));
    h += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"4\">");
    h += QStringLiteral("<tr><th align=\"left\">%1</th><th align=\"left\">%2</th></tr>")
             .arg(esc(tr("Metric")), esc(tr("Value")));
    for (const auto &[label, value] : metrics(r))
        h += QStringLiteral("<tr><td>%1</td><td>%2</td></tr>").arg(esc(label), esc(value));
    h += QStringLiteral("</table>");

    if (!m_sphere.isNull()) {
        m_document->addResource(QTextDocument::ImageResource, sphereUrl(), QVariant(m_sphere));
        h += QStringLiteral("<h2>%1</h2>").arg(esc(tr("Magnetometer samples")));
        h += QStringLiteral("<p>%1</p>").arg(esc(sphereCaption()));
        h += QStringLiteral("<p><img src=\"%1\" width=\"%2\" height=\"%3\"></p>")
                 .arg(sphereUrl().toString())
                 .arg(m_sphere.width() / 2)
                 .arg(m_sphere.height() / 2);
    }

    deviceSection(h);

    const bool trouble = verdict == QLatin1String("fail") || verdict == QLatin1String("warn");
    if (trouble && r.kind == QLatin1String("magnetometer")) {
        h += QStringLiteral("<h2>%1</h2>").arg(esc(tr("Troubleshooting (HiPNUC manual v1.7.1, 9.31 and 9.32)")));
        h += QStringLiteral("<p>%1</p>")
                 .arg(esc(calib::MagCalProcedure::troubleshooting()).replace(QLatin1Char('\n'), QStringLiteral("<br>")));
        h += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"4\">");
        h += QStringLiteral("<tr><th align=\"left\">%1</th><th align=\"left\">%2</th><th align=\"left\">%3</th></tr>")
                 .arg(esc(tr("Cause")), esc(tr("Typical sign")), esc(tr("What to do")));
        const QString causes[][3] = {
            {tr("Strong magnetic interference around"), tr("STAT=4 or a jumping heading"),
             tr("Calibrate outdoors in an open space")},
            {tr("Rotation not done as described"), tr("PROGRESS grows slowly or stops"),
             tr("Turn fully and evenly about every axis")},
            {tr("The module moved while turning"), tr("Calibration finishes but the heading is poor"),
             tr("Keep it in place, only turn it")},
            {tr("Module and carrier moved relative to each other"), tr("Larger heading error after remounting"),
             tr("Calibrate the module and the carrier again, as one")},
        };
        for (const auto &c : causes)
            h += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>").arg(esc(c[0]), esc(c[1]), esc(c[2]));
        h += QStringLiteral("</table>");
        h += QStringLiteral("<p>%1</p>")
                 .arg(esc(tr("Indoors the field is often distorted in ways no calibration removes: if the heading "
                             "stays poor after a good calibration, prefer the 6-axis mode there.")));
    }
    if (!r.folder.isEmpty())
        h += QStringLiteral("<p style=\"color: #666;\">%1</p>")
                 .arg(esc(tr("Written by ImuDesk from the run kept in %1").arg(QDir::toNativeSeparators(r.folder))));
    h += QStringLiteral("</body></html>");
    m_html = h;
    m_document->setHtml(m_html);
}

QString CalibrationReport::sphereCaption() const
{
    if (m_sphere.isNull())
        return {};
    // The figures come from the run's result, as in the metrics table above.
    const int samples = m_record.result.value(QStringLiteral("samples")).toInt(int(magSamples(m_samples).size()));
    if (m_sphere.width() > kSphereSize)
        return tr("Left: the %1 samples of the run as measured (raw). Right: the same samples corrected by the run's "
                  "hard and soft iron; the green cells are the directions they cover, %2 % of the sphere.")
            .arg(samples)
            .arg(m_record.result.value(QStringLiteral("coverage_pct")).toDouble(), 0, 'f', 0);
    return tr("The %1 samples of the run as measured (raw), around their mean; the green cells are the directions "
              "they point to. The run has no usable correction to show them corrected.")
        .arg(samples);
}

QString CalibrationReport::deviceVerdictText(const calib::CalibrationRecord &record)
{
    const QJsonObject device = record.result.value(QStringLiteral("device_calibration")).toObject();
    if (device.isEmpty())
        return {};
    const QString verdict = device.value(QStringLiteral("verdict")).toString();
    QStringList parts{verdict == QLatin1String("running") ? tr("still running") : verdictText(verdict)};
    const QString message = device.value(QStringLiteral("message")).toString();
    if (!message.isEmpty())
        parts << message;
    if (device.value(QStringLiteral("stat")).toInt(-1) >= 0)
        parts << tr("Last reply: STAT=%1, PROGRESS=%2.")
                     .arg(device.value(QStringLiteral("stat")).toInt())
                     .arg(device.value(QStringLiteral("progress")).toInt());
    return parts.join(QLatin1Char(' '));
}

void CalibrationReport::deviceSection(QString &h) const
{
    const QString text = deviceVerdictText(m_record);
    if (text.isEmpty())
        return;
    auto esc = [](const QString &s) { return s.toHtmlEscaped(); };
    const QString verdict = m_record.result.value(QStringLiteral("device_calibration")).toObject().value(QStringLiteral("verdict")).toString();
    const QString colour = verdict == QLatin1String("pass") ? QStringLiteral("#1b7f2a")
        : verdict == QLatin1String("fail")                  ? QStringLiteral("#b00020")
                                                            : QStringLiteral("#a66300");
    h += QStringLiteral("<h2>%1</h2>").arg(esc(tr("The device's own calibration")));
    h += QStringLiteral("<p>%1</p>")
             .arg(esc(tr("The module's calibration (MCAL) is a separate run with its own verdict; the verdict and "
                         "the metrics above are ImuDesk's fit of the raw samples.")));
    h += QStringLiteral("<p><b>%1</b> <span style=\"color: %2;\">%3</span></p>")
             .arg(esc(tr("Device's verdict:")), colour, esc(text));
}

QString CalibrationReport::plainText() const
{
    return m_document->toPlainText();
}

bool CalibrationReport::writePdf(const QString &path, QString *error)
{
    QString why;
    if (PdfOutput::write(*m_document, tr("ImuDesk calibration report"), path, &why))
        return true;
    qCWarning(lcCalReport) << why;
    if (error)
        *error = why;
    return false;
}

} // namespace imudesk::ui
