#include "calibration/gyro_scale_wizard.h"
#include "calibration/turn_gauge.h"
#include "common/work_place_size.h"

#include "device/device_session.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/ascii_reply.h"

#include <QJsonObject>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QWizardPage>

#include <cmath>

namespace imudesk::ui {

GyroScaleWizard::GyroScaleWizard(device::DeviceSession &session, QWidget *parent)
    : QWizard(parent),
      m_session(session),
      m_device(session)
{
    setWindowTitle(tr("Gyro scale factor calibration"));
    fitWorkPlace(this, QSize(960, 660), parent); // room for every text, bounded by the screen

    auto *prepare = new QWizardPage;
    prepare->setTitle(tr("Preparation"));
    auto *pl = new QVBoxLayout(prepare);
    auto *checklist = new QLabel(
        tr("<ul><li>Place the module, with the robot or vehicle it is fixed to, on a level, flat floor.</li>"
           "<li>Keep the temperature steady and avoid vibration (motors off).</li>"
           "<li>Mark the start position: you must stop on the same mark, within 5 deg.</li>"
           "<li>Turn at an even 20-100 deg/s (5-20 s per turn), in either direction, without pausing.</li>"
           "<li>More turns give a smaller error: 720 deg (2 turns) to 1800 deg (5 turns).</li></ul>"
           "Keep the module still for a few seconds after pressing Start: ImuDesk measures the gyro bias first."));
    checklist->setWordWrap(true);
    pl->addWidget(checklist);
    // What the module sends now: ImuDesk follows the turn on the streamed gyroscope (the
    // module's own calibration does not need the stream). Turning the output on is offered
    // only when the gyroscope data is missing or too slow.
    m_streamStatus = new QLabel;
    m_streamStatus->setObjectName(QStringLiteral("gyroStreamStatus"));
    m_streamStatus->setWordWrap(true);
    pl->addWidget(m_streamStatus);
    m_enableOutput = new QPushButton(tr("Turn on HI91 at 100 Hz (LOG HI91 ONTIME 0.01)"));
    m_enableOutput->setObjectName(QStringLiteral("enableGyroOutput"));
    m_enableOutput->setToolTip(tr("Sends LOG HI91 ONTIME 0.01: the float IMU frame, gyroscope included, every 10 ms. "
                                  "Until SAVECONFIG it lasts until the module restarts."));
    m_enableOutput->hide();
    pl->addWidget(m_enableOutput, 0, Qt::AlignLeft);
    pl->addStretch(1);
    setPage(PreparePage, prepare);

    auto *runPage = new QWizardPage;
    runPage->setTitle(tr("Turn the module"));
    auto *rl = new QVBoxLayout(runPage);
    m_angle = new QSpinBox;
    m_angle->setRange(calib::GyroCalSession::kMinAngle, calib::GyroCalSession::kMaxAngle);
    m_angle->setSingleStep(360);
    m_angle->setValue(720);
    m_angle->setSuffix(tr(" deg"));
    m_start = new QPushButton(tr("Start"));
    m_stop = new QPushButton(tr("Stop"));
    m_stop->setEnabled(false);
    m_guidance = new QLabel(m_run.guidance());
    m_guidance->setWordWrap(true);
    QFont big = m_guidance->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    m_guidance->setFont(big);
    m_progress = new QProgressBar;
    m_progress->setFormat(tr("%v of %m deg"));
    m_rate = new QProgressBar;
    m_rate->setRange(0, 120);
    m_rate->setFormat(tr("rate %v deg/s (band 20-100)"));
    m_readout = new QLabel;
    m_readout->setWordWrap(true);
    m_deviceStatus = new QLabel;
    m_deviceStatus->setWordWrap(true);
    auto *row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Angle:")));
    row->addWidget(m_angle);
    row->addWidget(m_start);
    row->addWidget(m_stop);
    row->addStretch();
    rl->addLayout(row);
    rl->addWidget(m_guidance);
    // The turn as a ring beside the figures: the angle, the laps, the stop mark.
    m_gauge = new TurnGauge;
    m_gauge->setObjectName(QStringLiteral("turnGauge"));
    m_gauge->setTarget(m_angle->value(), calib::GyroScaleRun::Options{}.stopToleranceDeg);
    connect(m_angle, &QSpinBox::valueChanged, this, [this](int deg) {
        if (m_start->isEnabled())
            m_gauge->setTarget(deg, calib::GyroScaleRun::Options{}.stopToleranceDeg);
    });
    m_progress->hide(); // until a run starts: the gauge shows the target meanwhile
    m_rate->hide();
    auto *figures = new QVBoxLayout;
    figures->addWidget(m_progress);
    figures->addWidget(m_rate);
    figures->addWidget(m_readout);
    figures->addWidget(m_deviceStatus);
    figures->addStretch();
    auto *work = new QHBoxLayout;
    work->addWidget(m_gauge, 3);
    work->addLayout(figures, 2);
    rl->addLayout(work, 1);
    setPage(RunPage, runPage);

    auto *resultPage = new QWizardPage;
    resultPage->setTitle(tr("Result"));
    auto *sl = new QVBoxLayout(resultPage);
    m_result = new QLabel;
    m_result->setWordWrap(true);
    sl->addWidget(m_result);
    setPage(ResultPage, resultPage);

    connect(m_start, &QPushButton::clicked, this, &GyroScaleWizard::startRun);
    connect(m_stop, &QPushButton::clicked, this, &GyroScaleWizard::stopRun);
    connect(&m_device, &calib::GyroCalSession::stateChanged, this, &GyroScaleWizard::onDeviceState);
    connect(&m_clock, &QTimer::timeout, this, &GyroScaleWizard::refresh);
    m_clock.setInterval(50);
    connect(m_enableOutput, &QPushButton::clicked, this, &GyroScaleWizard::enableGyroOutput);
    connect(&m_session, &device::DeviceSession::commandFinished, this,
            [this](quint64 id, const protocol::hipnuc::AsciiReply &reply) {
                if (id != m_outputCommand)
                    return;
                m_outputCommand = 0;
                if (!reply.ok())
                    m_streamStatus->setText(tr("The module refused LOG HI91 ONTIME 0.01 (%1). Check the output in "
                                               "Device ▸ Configuration.")
                                                .arg(reply.errorLine.empty() ? tr("no answer")
                                                                             : QString::fromStdString(reply.errorLine)));
                checkStream();
            });
    m_streamClock.setInterval(kStreamCheckMs);
    connect(&m_streamClock, &QTimer::timeout, this, &GyroScaleWizard::checkStream);
    m_streamSeq = m_session.store().totalAppended();
    m_streamSince.start();
    m_streamClock.start();
    m_streamStatus->setText(tr("Gyroscope data: checking what the module sends…"));
    // Next stays off on the run page until the device has answered STOP.
    connect(this, &QWizard::currentIdChanged, this, [this](int id) {
        if (id == RunPage && !m_done)
            button(QWizard::NextButton)->setEnabled(false);
        if (id == PreparePage)
            m_streamClock.start();
        else
            m_streamClock.stop();
    });
}

void GyroScaleWizard::checkStream()
{
    // Gyroscope samples since the last check, over the time it took.
    const device::SampleStore &store = m_session.store();
    const auto batch = store.since(m_streamSeq, SIZE_MAX, &m_streamSeq);
    const double seconds = double(m_streamSince.restart()) / 1000.0;
    size_t gyro = 0;
    for (const model::Sample &sample : batch)
        gyro += (sample.fields & model::FieldGyr) ? 1 : 0;
    m_gyroRateHz = seconds > 0.0 ? double(gyro) / seconds : 0.0;
    const bool enough = m_gyroRateHz >= kMinGyroRateHz;
    if (m_outputCommand == 0) {
        if (enough)
            m_streamStatus->setText(tr("Gyroscope data: %1 Hz. Ready: ImuDesk will follow the turn.")
                                        .arg(m_gyroRateHz, 0, 'f', 0));
        else if (gyro == 0)
            m_streamStatus->setText(tr("No gyroscope data arrives: the module's calibration still works, but ImuDesk "
                                       "cannot show the angle turned or when to stop. Turn the HI91 output on."));
        else
            m_streamStatus->setText(tr("Gyroscope data: %1 Hz, too slow to follow the turn (ImuDesk needs %2 Hz or "
                                       "more). Turn the HI91 output on at 100 Hz.")
                                        .arg(m_gyroRateHz, 0, 'f', 0)
                                        .arg(kMinGyroRateHz, 0, 'f', 0));
    }
    m_enableOutput->setVisible(!enough);
    m_enableOutput->setEnabled(!enough && m_outputCommand == 0 && m_session.state() == device::SessionState::Connected);
}

void GyroScaleWizard::enableGyroOutput()
{
    m_outputCommand = m_session.sendCommand(protocol::hipnuc::commands::logOnTime(protocol::hipnuc::Message::HI91, 0.01));
    m_enableOutput->setEnabled(false);
    m_streamStatus->setText(tr("Sending LOG HI91 ONTIME 0.01…"));
}

bool GyroScaleWizard::validateCurrentPage()
{
    return currentId() != RunPage || m_done;
}

void GyroScaleWizard::startRun()
{
    calib::GyroScaleRun::Options o;
    o.targetDeg = m_angle->value();
    o.legs = 1; // USRCAL: one direction
    o.biasWindowS = 1.0;
    m_run = calib::GyroScaleRun(o);
    m_run.start();
    m_target = m_angle->value();
    m_rows.columns = {QStringLiteral("time_ms"), QStringLiteral("gyr_x"), QStringLiteral("gyr_y"),
                      QStringLiteral("gyr_z"),   QStringLiteral("acc_x"), QStringLiteral("acc_y"),
                      QStringLiteral("acc_z")};
    m_rows.rows.clear();
    m_seq = m_session.store().totalAppended(); // from now on
    m_done = false;
    button(QWizard::NextButton)->setEnabled(false);
    if (!m_device.start(m_angle->value())) {
        m_deviceStatus->setText(m_device.message());
        return;
    }
    m_progress->setRange(0, m_angle->value());
    m_gauge->setTarget(m_angle->value(), o.stopToleranceDeg);
    m_gauge->clear();
    m_progress->show();
    m_rate->show();
    m_start->setEnabled(false);
    m_angle->setEnabled(false);
    m_stop->setEnabled(true);
    m_clock.start();
}

void GyroScaleWizard::stopRun()
{
    m_device.stop();
    m_stop->setEnabled(false);
}

void GyroScaleWizard::refresh()
{
    uint64_t next = m_seq;
    const auto samples = m_session.store().since(m_seq, SIZE_MAX, &next);
    m_seq = next;
    for (const auto &s : samples) {
        if (!(s.fields & model::FieldGyr))
            continue;
        const bool acc = s.fields & model::FieldAcc;
        m_run.addSample(s.deviceTimeMs, {s.gyr.x, s.gyr.y, s.gyr.z},
                        acc ? Eigen::Vector3d(s.acc.x, s.acc.y, s.acc.z) : Eigen::Vector3d::Zero());
        if (m_rows.rows.size() < CalibrationRunSaver::kMaxRows)
            m_rows.rows.push_back({double(s.deviceTimeMs), s.gyr.x, s.gyr.y, s.gyr.z, acc ? s.acc.x : 0.0,
                                   acc ? s.acc.y : 0.0, acc ? s.acc.z : 0.0});
    }
    m_guidance->setText(m_run.guidance());
    const double angle = m_run.state() == calib::GyroScaleRun::State::Finished && !m_run.result().legs.empty()
        ? std::abs(m_run.result().legs.back().angleDeg)
        : std::abs(m_run.currentAngleDeg());
    m_progress->setValue(int(std::min(angle, double(m_progress->maximum()))));
    m_rate->setValue(int(std::min(std::abs(m_run.currentRateDps()), 120.0)));
    m_gauge->setProgress(angle, m_run.currentRateDps());
    m_readout->setText(tr("%1 deg turned (%2 turns), rate %3 deg/s %4")
                           .arg(angle, 0, 'f', 1)
                           .arg(angle / 360.0, 0, 'f', 2)
                           .arg(std::abs(m_run.currentRateDps()), 0, 'f', 1)
                           .arg(m_run.state() == calib::GyroScaleRun::State::Turning
                                    ? (m_run.rateInBand() ? tr("(in band)") : tr("(outside 20-100 deg/s)"))
                                    : QString()));
}

void GyroScaleWizard::onDeviceState(calib::GyroCalSession::State state, const QString &message)
{
    m_deviceStatus->setText(message);
    if (state == calib::GyroCalSession::State::Succeeded || state == calib::GyroCalSession::State::Failed) {
        refresh();
        m_clock.stop();
        m_start->setEnabled(true);
        m_angle->setEnabled(true);
        m_stop->setEnabled(false);
        m_done = true;
        saveRun();
        m_result->setText(resultText() + QStringLiteral("\n\n") + m_saver.statusText());
        button(QWizard::NextButton)->setEnabled(true);
    }
}

void GyroScaleWizard::saveRun()
{
    m_saver.save(QStringLiteral("gyro_scale"), resultJson(), m_rows);
}

QJsonObject GyroScaleWizard::resultJson() const
{
    const bool ok = m_device.state() == calib::GyroCalSession::State::Succeeded;
    const calib::GyroScaleRun::Result r = m_run.result();
    QJsonObject o;
    o.insert(QStringLiteral("target_deg"), m_target);
    o.insert(QStringLiteral("device_ok"), ok);
    o.insert(QStringLiteral("device_reply"), m_device.message());
    const bool estimate = !r.legs.empty();
    o.insert(QStringLiteral("estimate_complete"), estimate);
    if (estimate) {
        const calib::GyroScaleRun::Leg &leg = r.legs.back();
        o.insert(QStringLiteral("scale_error_pct"), r.scaleErrorPct);
        o.insert(QStringLiteral("bias_dps"), r.biasDps);
        o.insert(QStringLiteral("axis_tilt_deg"), r.axisTiltDeg);
        o.insert(QStringLiteral("odr_hz"), r.odrHz);
        o.insert(QStringLiteral("angle_deg"), leg.angleDeg);
        o.insert(QStringLiteral("duration_s"), leg.durationS);
        o.insert(QStringLiteral("mean_rate_dps"), leg.meanRateDps);
        o.insert(QStringLiteral("in_band_pct"), leg.inBandPct);
        o.insert(QStringLiteral("uniformity_pct"), leg.uniformityPct);
        o.insert(QStringLiteral("stopped_in_window"), leg.stoppedInWindow);
        o.insert(QStringLiteral("acceptable"), r.acceptable);
    }
    // pass: the device took it and our run met the manual's conditions; warn: taken, but
    // the run was uneven or we could not check it; fail: the device refused it.
    const char *verdict = !ok ? "fail" : estimate && r.acceptable ? "pass" : "warn";
    o.insert(QStringLiteral("verdict"), QLatin1String(verdict));
    o.insert(QStringLiteral("reason"),
             !ok ? tr("The device rejected the run: %1").arg(m_device.message())
                 : estimate ? r.summary
                            : tr("The device accepted the run, but ImuDesk saw no complete turn to check it."));
    return o;
}

QString GyroScaleWizard::resultText() const
{
    const bool ok = m_device.state() == calib::GyroCalSession::State::Succeeded;
    const calib::GyroScaleRun::Result r = m_run.result();
    QString text = ok ? tr("The device accepted the calibration (OK).") : tr("The device rejected the run (ERR).");
    text += QLatin1Char('\n') + m_device.message() + QLatin1Char('\n');
    if (!r.legs.empty())
        text += tr("ImuDesk's estimate from the same samples: %1").arg(r.summary);
    else
        text += tr("ImuDesk saw no complete turn, so it has no estimate of its own.");
    return text;
}

} // namespace imudesk::ui
