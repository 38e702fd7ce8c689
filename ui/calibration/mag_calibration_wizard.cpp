#include "calibration/mag_calibration_wizard.h"

#include "calib/mag_calibrator.h"
#include "device/device_session.h"
#include "settings/setting_catalog.h"
#include "calibration/mag_sphere_view.h"
#include "calibration/rotation_guide.h"
#include "common/work_place_size.h"

#include <QHBoxLayout>
#include <QJsonObject>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <QWizardPage>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

namespace {
// The verdict as a coloured headline: green pass, amber warn, red fail or refused.
void setVerdictHeadline(QLabel *label, calib::MagVerdict verdict, const QString &text)
{
    const char *colour = verdict == calib::MagVerdict::Pass ? "#2e7d32"
        : verdict == calib::MagVerdict::Warn                 ? "#e65100"
                                                             : "#c62828";
    label->setStyleSheet(QStringLiteral("QLabel { color: white; background: %1; border-radius: 4px; padding: 6px 10px;"
                                        " font-weight: bold; }")
                             .arg(QLatin1String(colour)));
    label->setText(text);
}

// A figure of the fit's accuracy: unknown (NaN) when the fit did not get that far,
// unbounded (inf) when the data does not determine it.
QString accuracyFigure(double v, int decimals)
{
    if (std::isnan(v))
        return MagCalibrationWizard::tr("unknown");
    if (std::isinf(v))
        return MagCalibrationWizard::tr("unbounded");
    return QString::number(v, 'f', decimals);
}

// A page that shows the field live: a sphere of the samples on the left, a verdict line and a
// table of figures on the right (objectName prefix + "Verdict" / "Figures"; the rotation page
// keeps its old names "liveVerdict" / "liveFigures").
struct LivePage {
    QWizardPage *page;
    MagSphereView *sphere;
    QVBoxLayout *side;
    QLabel *verdict;
    QLabel *figures;
};
LivePage livePage(const QString &title, const QString &subtitle, const QString &name, int sphereSize,
                  const QString &figuresTip)
{
    LivePage p{};
    p.page = new QWizardPage;
    p.page->setTitle(title);
    p.page->setSubTitle(subtitle);
    auto *row = new QHBoxLayout(p.page);
    p.sphere = new MagSphereView;
    p.sphere->setObjectName(name + QStringLiteral("Sphere"));
    p.sphere->setMinimumSize(sphereSize, sphereSize);
    row->addWidget(p.sphere, 3);
    p.side = new QVBoxLayout;
    p.verdict = new QLabel;
    p.verdict->setObjectName(name + QStringLiteral("Verdict"));
    p.verdict->setWordWrap(true);
    p.figures = new QLabel;
    p.figures->setObjectName(name + QStringLiteral("Figures"));
    p.figures->setTextFormat(Qt::RichText);
    p.figures->setToolTip(figuresTip);
    p.side->addWidget(p.verdict);
    p.side->addWidget(p.figures);
    row->addLayout(p.side, 2);
    return p;
}

QWizardPage *textPage(const QString &title, const QString &text)
{
    auto *page = new QWizardPage;
    page->setTitle(title);
    auto *l = new QVBoxLayout(page);
    auto *label = new QLabel(text);
    label->setWordWrap(true);
    l->addWidget(label);
    l->addStretch();
    return page;
}
} // namespace

MagCalibrationWizard::MagCalibrationWizard(device::DeviceSession &session, const model::FirmwareVersion &firmware,
                                           QWidget *parent)
    : QWizard(parent),
      m_session(session),
      m_firmware(firmware),
      m_device(session),
      m_config(session)
{
    setWindowTitle(tr("Magnetometer calibration"));
    auto *intro = textPage(tr("Before you start"),
                           tr("Calibrate the magnetometer when you use the 9-axis (AHRS) mode, where the heading follows "
                              "magnetic north. Without a magnetometer calibration, or where the field is disturbed, use "
                              "the 6-axis mode instead.\n\nBest: outdoors in an open space, more than 5 m from "
                              "buildings and vehicles. Acceptable: indoors, more than 30 cm from iron furniture, "
                              "monitors, motors, transformers, chargers and phones.\n\nIf the module is mounted on a "
                              "PCB, in a housing or on a robot, calibrate it together with them, as one rigid body: "
                              "calibrating the module alone does not help once it is mounted."));
    // What the wizard will ask for, and which of the module's own calibrations its firmware has.
    auto *steps = new QLabel(stepsText());
    steps->setObjectName(QStringLiteral("introSteps"));
    steps->setTextFormat(Qt::RichText);
    steps->setWordWrap(true);
    static_cast<QVBoxLayout *>(intro->layout())->insertWidget(1, steps);
    // The rotations the calibration asks for, drawn.
    auto *guide = new RotationGuide;
    guide->setObjectName(QStringLiteral("rotationGuide"));
    static_cast<QVBoxLayout *>(intro->layout())->insertWidget(2, guide, 1);
    setPage(IntroPage, intro);

    auto *mode = textPage(tr("Working mode"),
                          tr("The calibration needs the 9-axis (AHRS) mode, CONFIG ATT MODE 1 (the factory "
                             "setting). ImuDesk reads the module's mode first and offers a switch only when it runs "
                             "in a 6-axis mode; the switch sends CONFIG ATT MODE 1, SAVECONFIG and REBOOT."));
    m_modeStatus = new QLabel;
    m_modeStatus->setObjectName(QStringLiteral("modeStatus"));
    m_modeStatus->setWordWrap(true);
    m_switchMode = new QPushButton(tr("Switch to 9-axis mode"));
    m_switchMode->setObjectName(QStringLiteral("switchModeButton"));
    m_switchMode->hide();
    auto *switchRow = new QHBoxLayout;
    switchRow->addWidget(m_switchMode);
    switchRow->addStretch();
    // Below the explanation: what the module runs now, and the switch when it is needed.
    // The modes the module can run in, the one it runs now marked once it is read.
    m_modeTable = new QLabel;
    m_modeTable->setObjectName(QStringLiteral("modeTable"));
    m_modeTable->setTextFormat(Qt::RichText);
    m_modeTable->setWordWrap(true);
    m_modeTable->setText(modeTableText());
    auto *modeLayout = static_cast<QVBoxLayout *>(mode->layout());
    modeLayout->insertWidget(1, m_modeStatus);
    modeLayout->insertLayout(2, switchRow);
    modeLayout->insertWidget(3, m_modeTable);
    connect(m_switchMode, &QPushButton::clicked, this, &MagCalibrationWizard::switchToAhrs);
    connect(&m_config, &settings::ConfigurationController::readFinished, this, &MagCalibrationWizard::showMode);
    connect(&m_config, &settings::ConfigurationController::applyFinished, this,
            [this](const settings::ConfigurationController::ApplyReport &report) {
                if (!m_switching)
                    return;
                if (!report.ok) {
                    m_switching = false;
                    m_switchMode->setEnabled(true);
                    setVerdictHeadline(m_modeStatus, calib::MagVerdict::Fail,
                                       tr("The module did not take ATT MODE 1 (%1). Check the connection and try "
                                          "again.")
                                           .arg(report.error.isEmpty() ? tr("read back differs") : report.error));
                    return;
                }
                m_modeStatus->setText(tr("ATT MODE 1 set; saving it (SAVECONFIG)…"));
                m_config.save();
            });
    connect(&m_config, &settings::ConfigurationController::actionFinished, this,
            [this](const QString &key, bool ok, const QString &detail) {
                if (!m_switching)
                    return;
                if (!ok) {
                    m_switching = false;
                    m_switchMode->setEnabled(true);
                    setVerdictHeadline(m_modeStatus, calib::MagVerdict::Fail,
                                       tr("%1 failed: %2. Try again, or save and restart from the Configuration "
                                          "panel.")
                                           .arg(key, detail));
                    return;
                }
                if (key == QLatin1String("SAVECONFIG")) {
                    m_modeStatus->setText(tr("Saved; restarting the module (REBOOT)…"));
                    m_config.reboot();
                } else if (key == QLatin1String("REBOOT")) {
                    m_switching = false;
                    m_modeStatus->setText(tr("The module restarts in the 9-axis mode; reading it back…"));
                    QTimer::singleShot(kRebootSettleMs, this, &MagCalibrationWizard::readMode);
                }
            });
    setPage(ModePage, mode);

    // The spot, judged live from the field as the user turns the module: the raw samples on a
    // sphere, the verdict, and the figures it comes from (the module's own iron fitted out first).
    const LivePage env = livePage(
        tr("Environment check"),
        tr("At the calibration spot, turn the module slowly through many orientations. The module's own iron is taken "
           "out of the field first; what is left must be the Earth's field (20-65 µT), the same in every orientation "
           "(within 10 µT), and steady while the module is still."),
        QStringLiteral("environment"), 300,
        tr("Raw |B|: the field strength as measured, the module's own iron included. Field at the spot: the strength "
           "once that iron is fitted out. Spread: how much it differs between orientations (5th to 95th percentile). "
           "Change while still: |B| drift while the gyro shows no turn."));
    m_envSphere = env.sphere;
    m_envSphere->setToolTip(tr("The raw field as it comes from the module (µT), one dot per sample"));
    m_envStatus = env.verdict;
    m_envFigures = env.figures;
    env.side->addStretch();
    setPage(EnvironmentPage, env.page);

    // The live figures that decide the verdict, as the user turns the module.
    const LivePage rot = livePage(
        tr("Turn the module"),
        tr("Keep it in place and turn it slowly (20-100 deg/s) at least one full turn about each axis, until the "
           "sphere is green all over. Usually 30-60 s."),
        QStringLiteral("live"), 360,
        tr("Coverage: share of the 80 sphere cells the field has pointed into. Largest gap: radius of the biggest "
           "uncovered area. Raw |B|: the field strength before calibration (its spread is the iron the fit removes). "
           "Fit: the field and the residual of ImuDesk's fit on the samples so far, refreshed every second."));
    m_sphere = rot.sphere;
    m_liveVerdict = rot.verdict;
    m_figures = rot.figures;
    QVBoxLayout *side = rot.side;
    side->addSpacing(12);
    m_startDevice = new QPushButton(tr("Start the device's calibration"));
    m_deviceProgress = new QProgressBar;
    m_deviceProgress->setRange(0, 100);
    m_deviceStatus = new QLabel;
    m_deviceStatus->setWordWrap(true);
    m_fit = new QPushButton(tr("Fit ImuDesk's calibration now"));
    side->addWidget(m_startDevice);
    side->addWidget(m_deviceProgress);
    side->addWidget(m_deviceStatus);
    side->addSpacing(12);
    side->addWidget(m_fit);
    side->addStretch();
    setPage(RotationPage, rot.page);

    auto *res = new QWizardPage;
    res->setTitle(tr("Result"));
    auto *resultPage = new QVBoxLayout(res);
    m_verdict = new QLabel;
    m_verdict->setObjectName(QStringLiteral("verdictHeadline"));
    m_verdict->setWordWrap(true);
    resultPage->addWidget(m_verdict);
    // The device's own run, with its own verdict: never mixed into ImuDesk's.
    m_deviceVerdict = new QLabel;
    m_deviceVerdict->setObjectName(QStringLiteral("deviceVerdict"));
    m_deviceVerdict->setWordWrap(true);
    resultPage->addWidget(m_deviceVerdict);
    auto *sl = new QHBoxLayout;
    resultPage->addLayout(sl, 1);
    m_resultLabel = new QLabel;
    m_resultLabel->setWordWrap(true);
    m_resultLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_after = new MagSphereView;
    auto *resultColumn = new QVBoxLayout;
    resultColumn->addWidget(m_resultLabel);
    m_savedLabel = new QLabel;
    m_savedLabel->setWordWrap(true);
    m_savedLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    resultColumn->addWidget(m_savedLabel);
    resultColumn->addStretch();
    sl->addLayout(resultColumn, 1);
    m_after->setMinimumSize(320, 320);
    sl->addWidget(m_after, 1);
    setPage(ResultPage, res);

    auto *heading = textPage(tr("Heading check"),
                             tr("Place the module level and turn it slowly one full turn (360 deg). The heading must "
                                "change continuously, without jumps of more than 10 deg; within +-5 deg of the true "
                                "directions is acceptable."));
    m_headingStatus = new QLabel;
    heading->layout()->addWidget(m_headingStatus);
    setPage(HeadingPage, heading);

    connect(m_startDevice, &QPushButton::clicked, this, [this] {
        refresh(); // the samples so far were taken before the device could change its output
        m_rawBeforeDevice = m_samples.size();
        m_deviceStarted = true;
        m_device.start(calib::MagCalProcedure::flowFor(m_firmware));
        m_startDevice->setEnabled(false);
        showDeviceVerdict();
    });
    connect(&m_device, &calib::MagCalSession::progressChanged, this, &MagCalibrationWizard::deviceProgressed);
    connect(&m_device, &calib::MagCalSession::finished, this, &MagCalibrationWizard::deviceFinished);
    connect(m_fit, &QPushButton::clicked, this, &MagCalibrationWizard::runFit);
    connect(this, &QWizard::currentIdChanged, this, &MagCalibrationWizard::pageChanged);
    connect(&m_clock, &QTimer::timeout, this, &MagCalibrationWizard::refresh);
    m_clock.start(50);
    connect(&m_fitClock, &QTimer::timeout, this, &MagCalibrationWizard::liveFit);
    m_fitClock.start(1000);
    m_seq = m_session.store().totalAppended();
    // A work place, not a dialog: the sphere gets room (>= 400 px on a 1366x768 screen).
    fitWorkPlace(this, QSize(1240, 860), parent);
}

void MagCalibrationWizard::readMode()
{
    if (m_config.busy())
        return;
    m_attMode.clear();
    m_switchMode->hide();
    m_modeStatus->setStyleSheet(QString());
    m_modeStatus->setText(tr("Reading the working mode from the module (LOG COMCONFIG)…"));
    m_config.readAll();
}

void MagCalibrationWizard::showMode(bool ok, const QString &error)
{
    if (!ok) {
        setVerdictHeadline(m_modeStatus, calib::MagVerdict::Fail,
                           tr("The working mode could not be read: %1. Check the connection, then press Back and "
                              "Next to read it again, or switch to the 9-axis mode anyway.")
                               .arg(error));
        m_switchMode->show();
        m_switchMode->setEnabled(true);
        return;
    }
    m_attMode = m_config.configuration().value(QStringLiteral("ATT.MODE")).value_or(QString());
    m_modeTable->setText(modeTableText());
    if (m_attMode == QLatin1String("1")) {
        setVerdictHeadline(m_modeStatus, calib::MagVerdict::Pass,
                           tr("The module runs in the 9-axis (AHRS) mode, ATT MODE 1: nothing to change. Press "
                              "Next."));
        m_switchMode->hide();
    } else {
        setVerdictHeadline(
            m_modeStatus, calib::MagVerdict::Warn,
            tr("The module runs in a 6-axis mode (ATT MODE %1): its heading ignores the magnetometer. Switch to the "
               "9-axis mode before you calibrate.")
                .arg(m_attMode.isEmpty() ? tr("not reported") : m_attMode));
        m_switchMode->show();
        m_switchMode->setEnabled(!m_switching);
    }
}

void MagCalibrationWizard::liveFit()
{
    if (currentId() != RotationPage || !m_collecting || m_showingRun || m_samples.size() < 30)
        return;
    // Every n-th sample, at most 3000: a second's work stays a few milliseconds.
    const size_t step = std::max<size_t>(1, m_samples.size() / 3000);
    std::vector<Eigen::Vector3d> subset;
    subset.reserve(m_samples.size() / step + 1);
    for (size_t i = 0; i < m_samples.size(); i += step)
        subset.push_back(m_samples[i]);
    // Fewer resampled fits than the final fit: the live verdict refreshes every second.
    calib::MagCalibrator::Options live;
    live.replicates = kLiveReplicates;
    m_live = calib::MagCalibrator(live).calibrate(subset);
    // "Pass" is said only as the final fit would say it: its 95 % bound from 12 resampled fits
    // is too rough near the limit (a live pass then fitted as a warning), so a live pass is
    // checked with the final fit's number of them.
    if (m_live.verdict == calib::MagVerdict::Pass)
        m_live = calib::MagCalibrator().calibrate(subset);
    m_haveLive = true;
    setVerdictHeadline(m_liveVerdict, m_live.verdict,
                       tr("So far: %1. %2").arg(calib::MagCalResult::verdictText(m_live.verdict), m_live.reason));
    m_figures->setText(liveFiguresText());
}

QString MagCalibrationWizard::stepsText() const
{
    const bool mcal = calib::MagCalProcedure::flowFor(m_firmware) == calib::MagCalProcedure::Flow::Mcal;
    QString rows;
    const auto step = [&rows](int n, const QString &what, const QString &detail) {
        rows += QStringLiteral("<tr><td valign=top><b>%1.</b></td><td valign=top><b>%2</b></td><td>%3</td></tr>")
                    .arg(n)
                    .arg(what, detail);
    };
    step(1, tr("Working mode"), tr("read from the module; a switch to 9-axis is offered when needed"));
    step(2, tr("Environment check"), tr("turn the module at the spot: the field is judged with its own iron taken out"));
    step(3, tr("Turn the module"),
         tr("slowly about every axis until the sphere is covered, usually 30-60 s; %1")
             .arg(mcal ? tr("the module calibrates itself at the same time (CONFIG MCAL, firmware %1)")
                             .arg(QString::fromStdString(m_firmware.toString()))
                       : tr("firmware %1 calibrates in the background in 9-axis mode")
                             .arg(QString::fromStdString(m_firmware.toString()))));
    step(4, tr("Result"), tr("ImuDesk's fit and the module's own verdict, side by side; saved with the samples"));
    step(5, tr("Heading check"), tr("one level turn: the heading must follow without jumps"));
    return QStringLiteral("<table cellspacing=6>") + rows + QStringLiteral("</table>");
}

QString MagCalibrationWizard::modeTableText() const
{
    const settings::SettingDefinition *d = settings::SettingCatalog::find(QStringLiteral("ATT.MODE"));
    if (!d)
        return {};
    QString rows;
    const std::pair<const char *, QString> modes[] = {
        {"0", tr("heading from the gyro alone: it drifts, the magnetometer is not used")},
        {"1", tr("heading follows magnetic north: needs this calibration")},
        {"4", tr("6-axis, for legged robots (firmware 1.7.x)")},
    };
    for (const auto &[value, meaning] : modes) {
        const bool current = m_attMode == QLatin1String(value);
        const QString name = settings::SettingCatalog::valueText(*d, QLatin1String(value));
        rows += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
                    .arg(current ? QStringLiteral("<b>%1</b>").arg(name.toHtmlEscaped()) : name.toHtmlEscaped(),
                         meaning.toHtmlEscaped(), current ? tr("◀ the module") : QString());
    }
    return QStringLiteral("<table cellspacing=6><tr><th align=left>%1</th><th align=left>%2</th><th></th></tr>")
               .arg(tr("ATT MODE"), tr("Heading"))
        + rows + QStringLiteral("</table>");
}

void MagCalibrationWizard::showEnvironment()
{
    using S = calib::MagEnvironmentJudge::Status;
    const S status = m_env.status();
    const calib::MagVerdict shade = status == S::Ok ? calib::MagVerdict::Pass
        : status == S::TurnMore                     ? calib::MagVerdict::Warn
                                                    : calib::MagVerdict::Fail;
    setVerdictHeadline(m_envStatus, shade, m_env.advice());
    m_envFigures->setText(environmentFiguresText());
}

QString MagCalibrationWizard::environmentFiguresText() const
{
    const auto row = [](const QString &name, const QString &value, const QString &unit) {
        return QStringLiteral("<tr><td>%1</td><td align=right><b>%2</b></td><td>%3</td></tr>").arg(name, value, unit);
    };
    const auto uT = [](std::optional<double> v) { return v ? QString::number(*v, 'f', 1) : QStringLiteral("–"); };
    QString rows = row(tr("Raw |B| now"), m_env.count() ? uT(m_env.rawFieldUt()) : QStringLiteral("–"), tr("µT"));
    rows += row(tr("Field at the spot"), uT(m_env.fittedFieldUt()), tr("µT (Earth: 20–65)"));
    rows += row(tr("Module's own iron"), uT(m_env.moduleIronUt()), tr("µT, removed by the calibration"));
    rows += row(tr("Spread"), m_env.ellipsoid() ? uT(m_env.spreadUt()) : QStringLiteral("–"),
                tr("µT between orientations (≤ 10)"));
    rows += row(tr("Change while still"), m_env.stillChangeUt() > 0 ? uT(m_env.stillChangeUt()) : QStringLiteral("–"),
                tr("µT (≤ 3)"));
    rows += row(tr("Directions"), QString::number(m_env.coveragePercent(), 'f', 0), tr("% of the sphere"));
    return QStringLiteral("<table cellspacing=4>") + rows + QStringLiteral("</table>");
}

QString MagCalibrationWizard::liveFiguresText() const
{
    if (m_showingRun) {
        // The fitted run: the figures of its result, as the result page, the saved run and the
        // report give them.
        const calib::MagCalResult &r = m_result;
        QString rows = tr("<tr><td>ImuDesk's fit</td><td align=right><b>%1</b></td><td></td></tr>")
                           .arg(calib::MagCalResult::verdictText(r.verdict));
        rows += tr("<tr><td>Coverage</td><td align=right><b>%1 %</b></td><td>of the field directions</td></tr>")
                    .arg(r.coveragePct, 0, 'f', 0);
        if (r.verdict != calib::MagVerdict::Refused)
            rows += tr("<tr><td>Fitted field</td><td align=right><b>%1</b></td><td>µT</td></tr>"
                       "<tr><td>Fit residual</td><td align=right><b>%2</b></td><td>µT RMS (%3 %)</td></tr>")
                        .arg(r.fieldUt, 0, 'f', 1)
                        .arg(r.residualRmsUt, 0, 'f', 2)
                        .arg(r.fitErrorPct, 0, 'f', 2);
        if (!std::isnan(r.predictedHeadingErrorDeg))
            rows += tr("<tr><td>Predicted heading error</td><td align=right><b>%1°</b></td><td>level module, 68 %; "
                       "95 %: %2°</td></tr>")
                        .arg(accuracyFigure(r.predictedHeadingErrorDeg, 2), accuracyFigure(r.predictedHeadingError95Deg, 2));
        rows += tr("<tr><td>Samples</td><td align=right><b>%1</b></td><td></td></tr>").arg(r.samples);
        return QStringLiteral("<table cellspacing=4>") + rows + QStringLiteral("</table>");
    }
    const calib::SphereCoverage &cov = m_sphere->coverage();
    QString rows = tr("<tr><td>Coverage</td><td align=right><b>%1 %</b></td><td>(%2 of %3 cells)</td></tr>")
                       .arg(cov.percent(), 0, 'f', 0)
                       .arg(cov.coveredCells())
                       .arg(calib::SphereCoverage::kCells);
    rows += tr("<tr><td>Largest gap</td><td align=right><b>%1°</b></td><td>radius</td></tr>")
                .arg(cov.largestGapDeg(), 0, 'f', 0);
    if (!m_samples.empty())
        rows += tr("<tr><td>Raw |B|</td><td align=right><b>%1–%2</b></td><td>µT</td></tr>")
                    .arg(m_minField, 0, 'f', 1)
                    .arg(m_maxField, 0, 'f', 1);
    if (m_haveLive && m_live.verdict != calib::MagVerdict::Refused)
        rows += tr("<tr><td>Fitted field</td><td align=right><b>%1</b></td><td>µT</td></tr>"
                   "<tr><td>Fit residual</td><td align=right><b>%2</b></td><td>µT RMS (%3 %)</td></tr>")
                    .arg(m_live.fieldUt, 0, 'f', 1)
                    .arg(m_live.residualRmsUt, 0, 'f', 2)
                    .arg(m_live.fitErrorPct, 0, 'f', 1);
    if (m_haveLive && !std::isnan(m_live.predictedHeadingErrorDeg))
        rows += tr("<tr><td>Predicted heading error</td><td align=right><b>%1°</b></td><td>level, 68 % (95 %: %4°; "
                   "pass &lt; %2°, refused &gt; %3°)</td></tr>")
                    .arg(accuracyFigure(m_live.predictedHeadingErrorDeg, 2))
                    .arg(calib::MagCalibrator::kWarnHeadingErrorDeg, 0, 'f', 1)
                    .arg(calib::MagCalibrator::kRefuseHeadingErrorDeg, 0, 'f', 0)
                    .arg(accuracyFigure(m_live.predictedHeadingError95Deg, 2));
    rows += tr("<tr><td>Samples</td><td align=right><b>%1</b></td><td></td></tr>").arg(m_samples.size());
    return QStringLiteral("<table cellspacing=4>") + rows + QStringLiteral("</table>");
}

void MagCalibrationWizard::switchToAhrs()
{
    if (m_config.busy())
        return;
    m_switching = true;
    m_switchMode->setEnabled(false);
    m_modeStatus->setText(tr("Setting ATT MODE 1…"));
    m_config.apply({{QStringLiteral("ATT.MODE"), QStringLiteral("1")}});
}

void MagCalibrationWizard::pageChanged(int id)
{
    if (id == EnvironmentPage) {
        m_env.reset();
        m_envSphere->clear();
        showEnvironment();
    }
    if (id == ModePage)
        readMode();
    if (id == RotationPage) {
        // A new collection, a new run: the fit of the last one no longer describes it.
        m_samples.clear();
        m_sphere->clear();
        m_sphere->clearCalibration();
        m_fitted = false;
        m_showingRun = false;
        m_collecting = true;
        m_rawBeforeDevice = 0;
        m_haveLive = false;
        m_liveVerdict->clear();
        m_liveVerdict->setStyleSheet(QString());
        m_figures->setText(liveFiguresText());
    }
    if (id == HeadingPage) {
        m_headingCheck.reset();
    }
    if (id == ResultPage) {
        // Samples came in after a refused fit: the result is the fit of all of them.
        if (!m_fitted || size_t(m_result.samples) != m_samples.size())
            runFit();
        showDeviceVerdict();
        saveRun();
    }
}

void MagCalibrationWizard::saveRun()
{
    if (m_runSaved)
        return;
    calib::SampleTable table;
    table.columns = {QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
    // The samples that were fitted, with the result computed from them.
    const size_t fitted = std::min(m_samples.size(), size_t(std::max(0, m_result.samples)));
    table.rows.reserve(fitted);
    for (size_t i = 0; i < fitted; ++i)
        table.rows.push_back({m_samples[i].x(), m_samples[i].y(), m_samples[i].z()});
    QJsonObject result = m_result.toJson();
    const QJsonObject device = deviceResultJson();
    if (!device.isEmpty())
        result.insert(QStringLiteral("device_calibration"), device);
    m_saver.save(QStringLiteral("magnetometer"), result, table);
    m_runSaved = true;
    m_savedLabel->setText(m_saver.statusText());
}

void MagCalibrationWizard::refresh()
{
    uint64_t next = m_seq;
    const auto samples = m_session.store().since(m_seq, SIZE_MAX, &next);
    m_seq = next;
    const int page = currentId();
    bool added = false;
    for (const auto &s : samples) {
        if (s.fields & model::FieldMag) {
            const Eigen::Vector3d m(s.mag.x, s.mag.y, s.mag.z);
            if (page == EnvironmentPage) {
                m_env.add(s.deviceTimeMs, m,
                          s.has(model::FieldGyr) ? std::optional<Eigen::Vector3d>({s.gyr.x, s.gyr.y, s.gyr.z})
                                                 : std::nullopt);
                m_envSphere->addSample(m);
            }
            if (page == RotationPage && m_collecting && m_samples.size() < kMaxSamples) {
                if (m_showingRun) // turning on after a refused fit: back to the live figures
                    showRunOnRotationPage(false);
                added = true;
                const double field = m.norm();
                m_minField = m_samples.empty() ? field : std::min(m_minField, field);
                m_maxField = m_samples.empty() ? field : std::max(m_maxField, field);
                m_samples.push_back(m);
                m_sphere->addSample(m);
            }
        }
        if (page == HeadingPage && (s.fields & model::FieldEuler))
            m_headingCheck.add(s.yaw);
    }
    if (page == EnvironmentPage)
        showEnvironment();
    if (page == RotationPage && added)
        m_figures->setText(liveFiguresText());
    if (page == HeadingPage)
        m_headingStatus->setText(tr("Turned %1 deg, largest step %2 deg: %3")
                                     .arg(m_headingCheck.turnedDeg(), 0, 'f', 0)
                                     .arg(m_headingCheck.maxJumpDeg(), 0, 'f', 1)
                                     .arg(headingCheckPassed() ? tr("the heading follows the turn smoothly.")
                                          : m_headingCheck.verdict() == calib::HeadingTurnCheck::Verdict::Jumped
                                          ? tr("the heading jumps: calibrate again (chapter 9.31).")
                                          : tr("keep turning.")));
}

bool MagCalibrationWizard::headingCheckPassed() const
{
    return m_headingCheck.passed();
}

void MagCalibrationWizard::runFit()
{
    refresh(); // every sample that has arrived, so that the fit and what the page shows agree
    m_result = calib::MagCalibrator().calibrate(m_samples);
    m_fitted = true;
    m_runSaved = false;
    // A usable fit is the run: the collection ends, so its figures stay the run's.
    if (m_result.usable())
        m_collecting = false;
    m_after->clearCalibration();
    m_after->setSamples(m_samples);
    if (m_result.usable())
        m_after->setCalibration(m_result.hardIron, m_result.softIron);
    m_after->showRun(m_result);
    m_resultLabel->setText(resultText());
    setVerdictHeadline(m_verdict, m_result.verdict,
                       tr("ImuDesk's fit: %1. %2").arg(calib::MagCalResult::verdictText(m_result.verdict), m_result.reason));
    showRunOnRotationPage(true);
}

void MagCalibrationWizard::showRunOnRotationPage(bool run)
{
    m_showingRun = run && m_fitted;
    m_sphere->clear();
    m_sphere->clearCalibration();
    m_sphere->setSamples(m_samples);
    if (m_showingRun) {
        if (m_result.usable())
            m_sphere->setCalibration(m_result.hardIron, m_result.softIron);
        m_sphere->showRun(m_result);
        m_haveLive = false;
        setVerdictHeadline(m_liveVerdict, m_result.verdict,
                           tr("ImuDesk's fit: %1. %2").arg(calib::MagCalResult::verdictText(m_result.verdict),
                                                           m_result.reason));
    }
    m_figures->setText(liveFiguresText());
}

void MagCalibrationWizard::deviceProgressed(int stat, int progress, const QString &message)
{
    m_deviceProgress->setValue(progress);
    m_deviceStatus->setText(stat >= 0 ? tr("Device: STAT=%1 PROGRESS=%2\n%3").arg(stat).arg(progress).arg(message)
                                      : message);
    // Still calibrating: the module has not changed its output yet, so what came in so far is
    // raw. (Samples read in the few milliseconds since the reply are counted too: the module
    // reports STAT=2, verifying, before it applies a calibration.)
    if (!m_device.procedure().finished()) {
        refresh();
        m_rawBeforeDevice = m_samples.size();
    }
    showDeviceVerdict();
}

void MagCalibrationWizard::deviceFinished(bool ok, const QString &message)
{
    m_startDevice->setEnabled(true);
    if (ok) {
        // The module now subtracts its own calibration from what it sends: those samples would
        // put a second, shifted sphere into ImuDesk's fit. Keep the raw ones, stop collecting.
        refresh();
        const bool trimmed = m_samples.size() > m_rawBeforeDevice;
        if (trimmed)
            m_samples.resize(m_rawBeforeDevice);
        m_collecting = false;
        m_deviceStatus->setText(message + QLatin1String("\n")
                                + tr("The device now corrects its own output, so ImuDesk's fit keeps the %n raw "
                                     "sample(s) collected before.",
                                     nullptr, int(m_samples.size())));
        // A fit that took samples of the corrected output no longer describes the raw sensor.
        if (m_fitted && size_t(m_result.samples) > m_samples.size())
            runFit();
        else if (trimmed && currentId() == RotationPage)
            showRunOnRotationPage(m_showingRun);
    } else {
        m_deviceStatus->setText(message + QLatin1String("\n\n") + calib::MagCalProcedure::troubleshooting());
    }
    showDeviceVerdict();
}

bool MagCalibrationWizard::deviceVerdict(calib::MagVerdict &verdict) const
{
    if (!m_deviceStarted)
        return false;
    switch (m_device.procedure().state()) {
    case calib::MagCalProcedure::State::Succeeded: verdict = calib::MagVerdict::Pass; break;
    case calib::MagCalProcedure::State::Failed: verdict = calib::MagVerdict::Fail; break;
    default: verdict = calib::MagVerdict::Warn; break;
    }
    return true;
}

QString MagCalibrationWizard::deviceResultText() const
{
    calib::MagVerdict verdict;
    if (!deviceVerdict(verdict))
        return {};
    const calib::MagCalProcedure &p = m_device.procedure();
    const QString state = p.finished() ? calib::MagCalResult::verdictText(verdict) : tr("still running");
    QString text = p.flow() == calib::MagCalProcedure::Flow::Mcal
        ? tr("The device's own calibration (CONFIG MCAL START): %1. %2").arg(state, p.message())
        : tr("The device's own calibration (in the background): %1. %2").arg(state, p.message());
    if (p.stat() >= 0)
        text += QLatin1Char(' ') + tr("Last reply: STAT=%1, PROGRESS=%2.").arg(p.stat()).arg(p.progress());
    return text;
}

QJsonObject MagCalibrationWizard::deviceResultJson() const
{
    calib::MagVerdict verdict;
    if (!deviceVerdict(verdict))
        return {};
    const calib::MagCalProcedure &p = m_device.procedure();
    QJsonObject o;
    o.insert(QStringLiteral("flow"), p.flow() == calib::MagCalProcedure::Flow::Mcal ? QStringLiteral("mcal")
                                                                                   : QStringLiteral("background"));
    o.insert(QStringLiteral("state"), QLatin1String(calib::MagCalProcedure::stateName(p.state())));
    o.insert(QStringLiteral("verdict"), p.finished() ? QLatin1String(calib::verdictName(verdict)) : QLatin1String("running"));
    o.insert(QStringLiteral("stat"), p.stat());
    o.insert(QStringLiteral("progress"), p.progress());
    o.insert(QStringLiteral("message"), p.message());
    return o;
}

void MagCalibrationWizard::showDeviceVerdict()
{
    calib::MagVerdict verdict;
    if (!deviceVerdict(verdict)) {
        m_deviceVerdict->setStyleSheet(QString());
        m_deviceVerdict->setText(tr("The device's own calibration (MCAL) was not run; the verdict above is "
                                    "ImuDesk's fit alone."));
        return;
    }
    setVerdictHeadline(m_deviceVerdict, verdict, deviceResultText());
}

QString MagCalibrationWizard::resultText() const
{
    if (!m_fitted)
        return tr("No fit yet.");
    const calib::MagCalResult &r = m_result;
    QString text;
    if (r.verdict != calib::MagVerdict::Refused)
        text += tr("Hard iron: %1, %2, %3 µT\nField: %4 µT\nFit error: %5 %\nResidual RMS: %6 µT\n")
                    .arg(r.hardIron.x(), 0, 'f', 2)
                    .arg(r.hardIron.y(), 0, 'f', 2)
                    .arg(r.hardIron.z(), 0, 'f', 2)
                    .arg(r.fieldUt, 0, 'f', 1)
                    .arg(r.fitErrorPct, 0, 'f', 2)
                    .arg(r.residualRmsUt, 0, 'f', 2);
    if (!std::isnan(r.predictedHeadingErrorDeg)) {
        // Only the full fit is refused for its accuracy; the other fits warn.
        const QString limits = r.mode == calib::MagCalMode::Full3D
            ? tr("level module; pass below %1°, refused above %2°")
                  .arg(calib::MagCalibrator::kWarnHeadingErrorDeg, 0, 'f', 1)
                  .arg(calib::MagCalibrator::kRefuseHeadingErrorDeg, 0, 'f', 0)
            : tr("level module; a warning above %1°").arg(calib::MagCalibrator::kWarnHeadingErrorDeg, 0, 'f', 1);
        text += tr("Predicted heading error: %1° in 68 % of cases, %5° in 95 % (%2)\nHard-iron uncertainty: +-%3 µT\n"
                   "Soft-iron uncertainty: +-%4 %\n")
                    .arg(accuracyFigure(r.predictedHeadingErrorDeg, 2), limits, accuracyFigure(r.hardIronSigmaUt, 2),
                         std::isnan(r.softIronSigmaPct) ? tr("kept from before") : accuracyFigure(r.softIronSigmaPct, 2),
                         accuracyFigure(r.predictedHeadingError95Deg, 2));
    }
    // Too few samples for a covariance: the ratio means nothing, a dash says so.
    text += tr("Coverage: %1 %\nEigenvalue ratio: %2\nSamples: %3")
                .arg(r.coveragePct, 0, 'f', 0)
                .arg(r.samples >= 3 && r.eigenRatio < 1e6 ? QString::number(r.eigenRatio, 'f', 1) : QStringLiteral("\u2014"))
                .arg(r.samples);
    if (!r.usable())
        text += QLatin1String("\n\n") + tr("What to check:") + QLatin1Char('\n') + calib::MagCalProcedure::troubleshooting();
    return text;
}

} // namespace imudesk::ui
