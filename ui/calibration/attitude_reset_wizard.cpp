#include "calibration/attitude_reset_wizard.h"
#include "protocol/hipnuc/ascii_command.h"
#include "common/work_place_size.h"

#include "device/device_session.h"

#include <QButtonGroup>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>
#include <QWizardPage>

#include <cmath>

namespace imudesk::ui {

namespace {
QString conditionsOf(int rst)
{
    switch (rst) {
    case 1:
        return AttitudeResetWizard::tr("Heading reset: the current heading becomes 0. Keep the module still. "
                                       "(Firmware 1.7.1 and later.)");
    case 2:
        return AttitudeResetWizard::tr("Relative zero: the current pitch and roll become 0, whatever they are. Keep "
                                       "the module still in the pose that should read level. CONFIG ATT RST 5 undoes it.");
    case 3:
        return AttitudeResetWizard::tr("Auto level: only when the module lies nearly level (pitch and roll within 5 "
                                       "deg), or upside down (roll within 5 deg of 180): it is levelled to 0/0 or "
                                       "0/180. Permanent: RST 5 does not undo it. Keep the module still.");
    case 5:
        return AttitudeResetWizard::tr("Cancel levelling: clears the relative pitch and roll set by RST 2; the "
                                       "absolute angles come back.");
    default:
        return {};
    }
}
} // namespace

AttitudeResetWizard::AttitudeResetWizard(device::DeviceSession &session, QWidget *parent)
    : QWizard(parent),
      m_session(session),
      m_still(calib::StillnessDetector::Options{1.0, 0.3, 0.005, 2.0})
{
    setWindowTitle(tr("Attitude reset and level"));
    fitWorkPlace(this, QSize(960, 660), parent); // room for every text, bounded by the screen

    auto *choose = new QWizardPage;
    choose->setTitle(tr("What to reset"));
    auto *cl = new QVBoxLayout(choose);
    m_variants = new QButtonGroup(this);
    const std::pair<int, QString> items[] = {{1, tr("Heading reset (ATT RST 1)")},
                                             {2, tr("Relative zero of pitch and roll (ATT RST 2)")},
                                             {3, tr("Auto level (ATT RST 3)")},
                                             {5, tr("Cancel levelling (ATT RST 5)")}};
    for (const auto &[id, text] : items) {
        auto *b = new QRadioButton(text);
        m_variants->addButton(b, id);
        cl->addWidget(b);
    }
    m_variants->button(3)->setChecked(true);
    m_conditions = new QLabel(conditionsOf(3));
    m_conditions->setWordWrap(true);
    cl->addWidget(m_conditions);
    cl->addStretch();
    setPage(ChoosePage, choose);
    connect(m_variants, &QButtonGroup::idClicked, this, [this](int id) { m_conditions->setText(conditionsOf(id)); });

    auto *check = new QWizardPage;
    check->setTitle(tr("Hold the module still"));
    auto *kl = new QVBoxLayout(check);
    m_status = new QLabel;
    m_status->setWordWrap(true);
    m_send = new QPushButton(tr("Send"));
    m_send->setEnabled(false);
    kl->addWidget(m_status);
    kl->addWidget(m_send);
    kl->addStretch();
    setPage(CheckPage, check);

    auto *result = new QWizardPage;
    result->setTitle(tr("Result"));
    auto *rl = new QVBoxLayout(result);
    m_result = new QLabel;
    m_result->setWordWrap(true);
    rl->addWidget(m_result);
    setPage(ResultPage, result);

    connect(m_send, &QPushButton::clicked, this, &AttitudeResetWizard::send);
    connect(&m_session, &device::DeviceSession::commandFinished, this, &AttitudeResetWizard::onCommandFinished);
    connect(&m_clock, &QTimer::timeout, this, &AttitudeResetWizard::refresh);
    connect(this, &QWizard::currentIdChanged, this, [this](int id) {
        if (id == CheckPage) {
            m_still.reset();
            m_seq = m_session.store().totalAppended();
            m_done = false;
            m_rows.columns = {QStringLiteral("time_ms"), QStringLiteral("gyr_x"), QStringLiteral("gyr_y"),
                              QStringLiteral("gyr_z"),   QStringLiteral("acc_x"), QStringLiteral("acc_y"),
                              QStringLiteral("acc_z"),   QStringLiteral("roll"),  QStringLiteral("pitch"),
                              QStringLiteral("yaw")};
            m_rows.rows.clear();
            m_clock.start(50);
            button(QWizard::NextButton)->setEnabled(false);
        } else {
            m_clock.stop();
        }
        if (id == ResultPage)
            m_result->setText(resultText() + (m_done ? QStringLiteral("\n\n") + m_saver.statusText() : QString()));
    });
}

void AttitudeResetWizard::setVariant(int rst)
{
    if (QAbstractButton *b = m_variants->button(rst)) {
        b->setChecked(true);
        m_conditions->setText(conditionsOf(rst));
    }
}

int AttitudeResetWizard::variant() const
{
    return m_variants->checkedId();
}

void AttitudeResetWizard::refresh()
{
    uint64_t next = m_seq;
    const auto samples = m_session.store().since(m_seq, SIZE_MAX, &next);
    m_seq = next;
    for (const auto &s : samples) {
        if ((s.fields & model::FieldGyr) && (s.fields & model::FieldAcc))
            m_still.add(s.deviceTimeMs, {s.gyr.x, s.gyr.y, s.gyr.z}, {s.acc.x, s.acc.y, s.acc.z});
        if (s.fields & model::FieldEuler) {
            m_roll = s.roll;
            m_pitch = s.pitch;
            m_yaw = s.yaw;
        }
        if (m_rows.rows.size() < CalibrationRunSaver::kMaxRows && (s.fields & model::FieldGyr)
            && (s.fields & model::FieldAcc))
            m_rows.rows.push_back({double(s.deviceTimeMs), s.gyr.x, s.gyr.y, s.gyr.z, s.acc.x, s.acc.y, s.acc.z,
                                   m_roll, m_pitch, m_yaw});
    }
    const bool still = m_still.isStill() && m_still.stillForS() >= kStillForS;
    const bool level = std::abs(m_pitch) < kLevelLimitDeg
        && (std::abs(m_roll) < kLevelLimitDeg || std::abs(std::abs(m_roll) - 180.0) < kLevelLimitDeg);
    QStringList problems;
    if (!still)
        problems << tr("not still yet (%1 of %2 s)").arg(m_still.stillForS(), 0, 'f', 1).arg(kStillForS, 0, 'f', 0);
    if (variant() == 3 && !level)
        problems << tr("not level: pitch %1, roll %2 deg (each must be within %3 deg of level or upside down)")
                        .arg(m_pitch, 0, 'f', 1)
                        .arg(m_roll, 0, 'f', 1)
                        .arg(kLevelLimitDeg, 0, 'f', 0);
    m_conditionsMet = problems.isEmpty();
    m_send->setEnabled(m_conditionsMet && m_pending == 0 && !m_done);
    m_status->setText(tr("Roll %1, pitch %2, yaw %3 deg; gyro spread %4 deg/s.\n%5")
                          .arg(m_roll, 0, 'f', 1)
                          .arg(m_pitch, 0, 'f', 1)
                          .arg(m_yaw, 0, 'f', 1)
                          .arg(m_still.gyroStdDps(), 0, 'f', 3)
                          .arg(m_conditionsMet ? tr("Ready: send CONFIG ATT RST %1.").arg(variant())
                                               : tr("Waiting: %1.").arg(problems.join(QStringLiteral("; ")))));
}

void AttitudeResetWizard::send()
{
    if (!m_conditionsMet || m_pending)
        return;
    m_sentStillForS = m_still.stillForS();
    m_sentGyroStd = m_still.gyroStdDps();
    m_sentAccStd = m_still.accStdG();
    m_sentRoll = m_roll;
    m_sentPitch = m_pitch;
    m_pending = m_session.sendCommand(protocol::hipnuc::commands::attReset(variant()));
    m_send->setEnabled(false);
}

void AttitudeResetWizard::onCommandFinished(quint64 id, const protocol::hipnuc::AsciiReply &reply)
{
    if (id != m_pending || m_pending == 0)
        return;
    m_pending = 0;
    m_done = true;
    m_ok = reply.ok();
    m_reply = m_ok ? tr("The device accepted CONFIG ATT RST %1 (OK).").arg(variant())
        : reply.status == protocol::hipnuc::AsciiReply::Status::Timeout
        ? tr("The device did not answer CONFIG ATT RST %1: its firmware may not know this variant.").arg(variant())
        : tr("The device refused CONFIG ATT RST %1 (ERR).").arg(variant());
    refresh(); // the attitude after the reply
    m_saver.save(QStringLiteral("attitude_reset"), resultJson(), m_rows);
    button(QWizard::NextButton)->setEnabled(true);
}

QJsonObject AttitudeResetWizard::resultJson() const
{
    QJsonObject o;
    o.insert(QStringLiteral("variant"), variant());
    o.insert(QStringLiteral("command"), QString::fromStdString(protocol::hipnuc::commands::attReset(variant()).text));
    o.insert(QStringLiteral("device_ok"), m_ok);
    o.insert(QStringLiteral("device_reply"), m_reply);
    o.insert(QStringLiteral("still_for_s"), m_sentStillForS);
    o.insert(QStringLiteral("gyro_std_dps"), m_sentGyroStd);
    o.insert(QStringLiteral("acc_std_g"), m_sentAccStd);
    o.insert(QStringLiteral("roll_before_deg"), m_sentRoll);
    o.insert(QStringLiteral("pitch_before_deg"), m_sentPitch);
    o.insert(QStringLiteral("roll_after_deg"), m_roll);
    o.insert(QStringLiteral("pitch_after_deg"), m_pitch);
    o.insert(QStringLiteral("yaw_after_deg"), m_yaw);
    o.insert(QStringLiteral("verdict"), QLatin1String(m_ok ? "pass" : "fail"));
    o.insert(QStringLiteral("reason"), m_reply);
    return o;
}

bool AttitudeResetWizard::validateCurrentPage()
{
    return currentId() != CheckPage || m_done;
}

QString AttitudeResetWizard::resultText() const
{
    if (!m_done)
        return tr("Nothing was sent.");
    return m_reply + QLatin1Char('\n')
        + tr("Attitude now: roll %1, pitch %2, yaw %3 deg. Save it with SAVECONFIG if it should survive a restart "
             "(RST 2).")
              .arg(m_roll, 0, 'f', 1)
              .arg(m_pitch, 0, 'f', 1)
              .arg(m_yaw, 0, 'f', 1);
}

} // namespace imudesk::ui
