#include "reports/station_report.h"

#include "reports/pdf_output.h"

#include <QDir>
#include <QTextDocument>

namespace imudesk::ui {

using station::Verdict;

namespace {
QString colourOf(Verdict v)
{
    switch (v) {
    case Verdict::Pass: return QStringLiteral("#1b7f2a");
    case Verdict::Fail: return QStringLiteral("#b00020");
    case Verdict::Skipped: return QStringLiteral("#666666");
    default: return QStringLiteral("#1f5fa8");
    }
}
QString timeText(const QDateTime &t)
{
    return t.isValid() ? t.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) : QString();
}
} // namespace

QString StationReport::html(const station::ModuleResult &m, const station::TestPlan &plan)
{
    auto esc = [](const QString &s) { return s.toHtmlEscaped(); };
    auto orUnknown = [](const QString &s) { return s.isEmpty() ? tr("unknown") : s; };
    QString h;
    h += QStringLiteral("<html><body style=\"font-family: sans-serif;\">");
    h += QStringLiteral("<h1>%1</h1>").arg(esc(tr("ImuDesk station report: %1").arg(orUnknown(m.serial))));
    h += QStringLiteral("<table cellspacing=\"0\" cellpadding=\"3\">");
    auto row = [&h, &esc](const QString &label, const QString &value) {
        h += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(esc(label), esc(value));
    };
    row(tr("Device"), orUnknown(m.product));
    row(tr("Serial number"), orUnknown(m.serial));
    row(tr("Firmware"), m.firmwareAfter.isEmpty() ? orUnknown(m.firmware)
                                                  : tr("%1, updated to %2").arg(orUnknown(m.firmware), m.firmwareAfter));
    row(tr("Port"), m.port);
    row(tr("Plan"), plan.name.isEmpty() ? tr("(unnamed)") : plan.name);
    row(tr("Attempt"), QString::number(m.attempt));
    row(tr("Started (UTC)"), timeText(m.started));
    row(tr("Finished (UTC)"), timeText(m.finished));
    h += QStringLiteral("</table>");
    h += QStringLiteral("<h2>%1 <span style=\"color: %2;\">%3</span></h2>")
             .arg(esc(tr("Verdict:")), colourOf(m.verdict),
                  esc(m.verdict == Verdict::Pass && m.marginal() ? tr("%1 (marginal)").arg(station::verdictText(m.verdict))
                                                                 : station::verdictText(m.verdict)));
    if (const QString f = m.failureSummary(); !f.isEmpty())
        h += QStringLiteral("<p>%1</p>").arg(esc(tr("Failed at %1").arg(f)));

    h += QStringLiteral("<h2>%1</h2>").arg(esc(tr("Steps")));
    for (size_t i = 0; i < m.steps.size(); ++i) {
        const station::StepResult &s = m.steps[i];
        h += QStringLiteral("<h3>%1. %2 <span style=\"color: %3;\">%4</span></h3>")
                 .arg(i + 1)
                 .arg(esc(s.title), colourOf(s.verdict), esc(station::verdictText(s.verdict)));
        if (!s.detail.isEmpty())
            h += QStringLiteral("<p>%1</p>").arg(esc(s.detail));
        if (s.values.empty())
            continue;
        h += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"4\">");
        h += QStringLiteral("<tr><th align=\"left\">%1</th><th align=\"right\">%2</th><th align=\"left\">%3</th>"
                            "<th align=\"left\">%4</th></tr>")
                 .arg(esc(tr("Value")), esc(tr("Measured")), esc(tr("Limit")), esc(tr("Result")));
        for (const station::Measurement &v : s.values) {
            // A value inside its marginal band passes, in the colour of a warning.
            const QString result = v.limit.isEmpty() ? QString() : !v.ok ? tr("outside") : v.marginal ? tr("marginal") : tr("within");
            h += QStringLiteral("<tr><td>%1</td><td align=\"right\">%2 %3</td><td>%4</td>"
                                "<td style=\"color: %5;\">%6</td></tr>")
                     .arg(esc(v.name), esc(QString::number(v.value, 'g', 5)), esc(v.unit), esc(v.limit),
                          !v.ok ? colourOf(Verdict::Fail) : v.marginal ? QStringLiteral("#b26a00") : colourOf(Verdict::Pass),
                          esc(result));
        }
        h += QStringLiteral("</table>");
    }
    if (!m.evidencePath.isEmpty())
        h += QStringLiteral("<p style=\"color: #666;\">%1</p>")
                 .arg(esc(tr("Evidence recording: %1").arg(QDir::toNativeSeparators(m.evidencePath))));
    h += QStringLiteral("</body></html>");
    return h;
}

bool StationReport::writePdf(const station::ModuleResult &module, const station::TestPlan &plan, const QString &path,
                             QString *error)
{
    QTextDocument doc;
    doc.setHtml(html(module, plan));
    return PdfOutput::write(doc, tr("ImuDesk station report"), path, error);
}

bool writeStationReport(const station::ModuleResult &module, const station::TestPlan &plan, const QString &path,
                        QString *error)
{
    return StationReport::writePdf(module, plan, path, error);
}

} // namespace imudesk::ui
