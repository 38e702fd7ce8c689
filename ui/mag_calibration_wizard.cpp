#include "mag_calibration_wizard.h"

#include "calib/mag_calibrator.h"
#include "device/device_session.h"
#include "mag_sphere_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <QWizardPage>

#include <cmath>

namespace imudesk::ui {

namespace {
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
      m_device(session)
{
    setWindowTitle(tr("Magnetometer calibration"));
    setPage(IntroPage,
            textPage(tr("Before you start"),
                     tr("Calibrate the magnetometer when you use the 9-axis (AHRS) mode, where the heading follows "
                        "magnetic north. Without a magnetometer calibration, or where the field is disturbed, use the "
                        "6-axis mode instead.\n\nBest: outdoors in an open space, more than 5 m from buildings and "
                        "vehicles. Acceptable: indoors, more than 30 cm from iron furniture, monitors, motors, "
                        "transformers, chargers and phones.\n\nIf the module is mounted on a PCB, in a housing or on "
                        "a robot, calibrate it together with them, as one rigid body: calibrating the module alone "
                        "does not help once it is mounted.")));

    auto *mode = textPage(tr("Working mode"),
                          tr("The calibration needs the 9-axis (AHRS) mode, CONFIG ATT MODE 1 (the factory "
                             "setting). If the module runs in a 6-axis mode, switch it: ImuDesk sends CONFIG ATT MODE "
                             "1, SAVECONFIG and REBOOT."));
    auto *switchButton = new QPushButton(tr("Switch to 9-axis mode"));
    mode->layout()->addWidget(switchButton);
    connect(switchButton, &QPushButton::clicked, this, &MagCalibrationWizard::switchToAhrs);
    setPage(ModePage, mode);

    auto *env = textPage(tr("Environment check"),
                         tr("Hold the module at the calibration spot and turn it to a few orientations. The field must "
                            "be 20-60 uT and vary by no more than 10 uT between orientations."));
    m_envStatus = new QLabel;
    m_envStatus->setWordWrap(true);
    env->layout()->addWidget(m_envStatus);
    setPage(EnvironmentPage, env);

    auto *rot = new QWizardPage;
    rot->setTitle(tr("Turn the module"));
    rot->setSubTitle(tr("Keep it in place and turn it slowly (20-100 deg/s) at least one full turn about each axis, "
                        "until the sphere is green all over. Usually 30-60 s."));
    auto *rl = new QHBoxLayout(rot);
    m_sphere = new MagSphereView;
    rl->addWidget(m_sphere, 2);
    auto *side = new QVBoxLayout;
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
    rl->addLayout(side, 1);
    setPage(RotationPage, rot);

    auto *res = new QWizardPage;
    res->setTitle(tr("Result"));
    auto *sl = new QHBoxLayout(res);
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
        m_device.start(calib::MagCalProcedure::flowFor(m_firmware));
        m_startDevice->setEnabled(false);
    });
    connect(&m_device, &calib::MagCalSession::progressChanged, this, [this](int stat, int progress, const QString &msg) {
        m_deviceProgress->setValue(progress);
        m_deviceStatus->setText(stat >= 0 ? tr("Device: STAT=%1 PROGRESS=%2\n%3").arg(stat).arg(progress).arg(msg) : msg);
    });
    connect(&m_device, &calib::MagCalSession::finished, this, [this](bool ok, const QString &msg) {
        m_startDevice->setEnabled(true);
        m_deviceStatus->setText(ok ? msg
                                   : msg + QLatin1String("\n\n") + calib::MagCalProcedure::troubleshooting());
    });
    connect(m_fit, &QPushButton::clicked, this, &MagCalibrationWizard::runFit);
    connect(this, &QWizard::currentIdChanged, this, &MagCalibrationWizard::pageChanged);
    connect(&m_clock, &QTimer::timeout, this, &MagCalibrationWizard::refresh);
    m_clock.start(50);
    m_seq = m_session.store().totalAppended();
}

void MagCalibrationWizard::switchToAhrs()
{
    m_session.sendCommand(QStringLiteral("CONFIG ATT MODE 1"));
    m_session.sendCommand(QStringLiteral("SAVECONFIG"));
    m_session.sendCommand(QStringLiteral("REBOOT"));
}

void MagCalibrationWizard::pageChanged(int id)
{
    if (id == EnvironmentPage)
        m_env.reset();
    if (id == RotationPage) {
        m_samples.clear();
        m_sphere->clear();
    }
    if (id == HeadingPage) {
        m_haveYaw = false;
        m_headingTurned = m_headingMaxJump = 0;
    }
    if (id == ResultPage) {
        if (!m_fitted)
            runFit();
        saveRun();
    }
}

void MagCalibrationWizard::saveRun()
{
    if (m_runSaved)
        return;
    calib::SampleTable table;
    table.columns = {QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
    table.rows.reserve(m_samples.size());
    for (const Eigen::Vector3d &m : m_samples)
        table.rows.push_back({m.x(), m.y(), m.z()});
    m_saver.save(QStringLiteral("magnetometer"), m_result.toJson(), table);
    m_runSaved = true;
    m_savedLabel->setText(m_saver.statusText());
}

void MagCalibrationWizard::refresh()
{
    uint64_t next = m_seq;
    const auto samples = m_session.store().since(m_seq, SIZE_MAX, &next);
    m_seq = next;
    const int page = currentId();
    for (const auto &s : samples) {
        if (s.fields & model::FieldMag) {
            const Eigen::Vector3d m(s.mag.x, s.mag.y, s.mag.z);
            if (page == EnvironmentPage)
                m_env.add(m);
            if (page == RotationPage && m_samples.size() < kMaxSamples) {
                m_samples.push_back(m);
                m_sphere->addSample(m);
            }
        }
        if (page == HeadingPage && (s.fields & model::FieldEuler)) {
            if (m_haveYaw) {
                double d = s.yaw - m_lastYaw;
                while (d > 180)
                    d -= 360;
                while (d < -180)
                    d += 360;
                m_headingTurned += std::abs(d);
                m_headingMaxJump = std::max(m_headingMaxJump, std::abs(d));
            }
            m_lastYaw = s.yaw;
            m_haveYaw = true;
        }
    }
    if (page == EnvironmentPage)
        m_envStatus->setText(m_env.advice());
    if (page == HeadingPage)
        m_headingStatus->setText(tr("Turned %1 deg, largest step %2 deg: %3")
                                     .arg(m_headingTurned, 0, 'f', 0)
                                     .arg(m_headingMaxJump, 0, 'f', 1)
                                     .arg(headingCheckPassed() ? tr("the heading follows the turn smoothly.")
                                          : m_headingMaxJump > kMaxHeadingJumpDeg
                                          ? tr("the heading jumps: calibrate again (chapter 9.31).")
                                          : tr("keep turning.")));
}

bool MagCalibrationWizard::headingCheckPassed() const
{
    return m_headingTurned >= 360.0 && m_headingMaxJump <= kMaxHeadingJumpDeg;
}

void MagCalibrationWizard::runFit()
{
    m_result = calib::MagCalibrator().calibrate(m_samples);
    m_fitted = true;
    m_runSaved = false;
    m_after->setSamples(m_samples);
    if (m_result.usable())
        m_after->setCalibration(m_result.hardIron, m_result.softIron);
    m_resultLabel->setText(resultText());
}

QString MagCalibrationWizard::resultText() const
{
    if (!m_fitted)
        return tr("No fit yet.");
    const calib::MagCalResult &r = m_result;
    QString text = tr("Verdict: %1\n%2\n\n").arg(calib::MagCalResult::verdictText(r.verdict), r.reason);
    if (r.verdict != calib::MagVerdict::Refused)
        text += tr("Hard iron: %1, %2, %3 uT\nField: %4 uT\nFit error: %5 %\nResidual RMS: %6 uT\n")
                    .arg(r.hardIron.x(), 0, 'f', 2)
                    .arg(r.hardIron.y(), 0, 'f', 2)
                    .arg(r.hardIron.z(), 0, 'f', 2)
                    .arg(r.fieldUt, 0, 'f', 1)
                    .arg(r.fitErrorPct, 0, 'f', 2)
                    .arg(r.residualRmsUt, 0, 'f', 2);
    text += tr("Coverage: %1 %\nEigenvalue ratio: %2\nSamples: %3")
                .arg(r.coveragePct, 0, 'f', 0)
                .arg(r.eigenRatio, 0, 'f', 1)
                .arg(r.samples);
    if (!r.usable())
        text += QLatin1String("\n\n") + tr("What to check:") + QLatin1Char('\n') + calib::MagCalProcedure::troubleshooting();
    return text;
}

} // namespace imudesk::ui
