#include "recording/replay_controls.h"

#include "record/replay_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

namespace imudesk::ui {

namespace {
QString clock(double s)
{
    const auto t = qint64(s);
    return QStringLiteral("%1:%2.%3")
        .arg(t / 60, 2, 10, QLatin1Char('0'))
        .arg(t % 60, 2, 10, QLatin1Char('0'))
        .arg(qint64((s - double(t)) * 10), 1, 10, QLatin1Char('0'));
}
} // namespace

const QList<double> &ReplayControls::speeds()
{
    static const QList<double> s = {0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 0.0};
    return s;
}

ReplayControls::ReplayControls(QWidget *parent) : QWidget(parent)
{
    m_play = new QPushButton(tr("Play"), this);
    m_play->setObjectName(QStringLiteral("play"));
    m_speed = new QComboBox(this);
    m_speed->setObjectName(QStringLiteral("speed"));
    for (double s : speeds())
        m_speed->addItem(s > 0 ? tr("%1×").arg(s) : tr("As fast as possible"), s);
    m_speed->setCurrentIndex(int(speeds().indexOf(1.0)));
    m_timeline = new QSlider(Qt::Horizontal, this);
    m_timeline->setObjectName(QStringLiteral("timeline"));
    m_timeline->setRange(0, 0);
    m_loop = new QCheckBox(tr("Loop"), this);
    m_loop->setObjectName(QStringLiteral("loop"));
    m_time = new QLabel(this);
    m_time->setObjectName(QStringLiteral("time"));
    m_linked = new QLabel(this);
    m_linked->setObjectName(QStringLiteral("linked"));
    m_linked->hide();

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    // One row: the dock below the charts keeps its height, the charts get the rest.
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    layout->addWidget(m_play);
    layout->addWidget(m_speed);
    layout->addWidget(m_timeline, 1);
    layout->addWidget(m_time);
    layout->addWidget(m_loop);
    layout->addWidget(m_linked);

    connect(m_play, &QPushButton::clicked, this, [this] {
        if (!m_session)
            return;
        if (m_playing)
            m_session->pause();
        else
            m_session->play();
    });
    connect(m_speed, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (m_session && i >= 0)
            m_session->setSpeed(m_speed->itemData(i).toDouble());
    });
    connect(m_loop, &QCheckBox::toggled, this, [this](bool on) {
        if (m_session)
            m_session->setLoop(on);
    });
    connect(m_timeline, &QSlider::sliderReleased, this, &ReplayControls::seekToSlider);
    connect(m_timeline, &QSlider::actionTriggered, this, [this](int action) {
        // Clicks and keys on the track seek at once; dragging seeks on release.
        if (action != QAbstractSlider::SliderMove)
            QMetaObject::invokeMethod(this, &ReplayControls::seekToSlider, Qt::QueuedConnection);
    });
    setSession(nullptr);
}

void ReplayControls::setSession(record::ReplaySession *session)
{
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_session = session;
    m_playing = false;
    m_duration = m_position = 0;
    setEnabled(m_session != nullptr);
    // A device of a recorded session: every device's replay follows these controls, on the
    // session's timeline; without a common pace, "as fast as possible" is not offered.
    const bool grouped = m_session && m_session->group();
    const int fastest = m_speed->findData(record::ReplaySession::kAsFastAsPossible);
    if (grouped && fastest >= 0)
        m_speed->removeItem(fastest);
    else if (!grouped && fastest < 0)
        m_speed->addItem(tr("As fast as possible"), record::ReplaySession::kAsFastAsPossible);
    m_linked->setVisible(grouped);
    m_linked->setText(tr("Session: all devices together"));
    m_linked->setToolTip(tr("This capture is one device of a recorded session. Play, pause, seek, speed and loop "
                            "act on every device of the session; the positions are times since the session "
                            "started, so one position is the same instant in every tab."));
    if (m_session) {
        connect(m_session, &record::ReplaySession::opened, this, &ReplayControls::onOpened);
        connect(m_session, &record::ReplaySession::positionChanged, this, &ReplayControls::onPosition);
        connect(m_session, &record::ReplaySession::playingChanged, this, &ReplayControls::onPlaying);
        connect(m_session, &QObject::destroyed, this, [this] { setSession(nullptr); });
        m_session->setSpeed(m_speed->currentData().toDouble());
        m_session->setLoop(m_loop->isChecked());
    }
    m_play->setText(tr("Play"));
    updateLabel();
}

void ReplayControls::onOpened(double durationS, const capture::CaptureHeader &header)
{
    m_deviceClock = header.value(capture::CaptureHeader::kHostTime) == "absent";
    m_time->setToolTip(m_deviceClock ? tr("This file is a raw byte dump: it has no arrival times, so the times come "
                                          "from the device's own clock (HI91/HI83 time stamps or NMEA UTC time).")
                                     : QString());
    m_duration = durationS;
    m_timeline->setRange(0, int(durationS * 1000));
    updateLabel();
}

void ReplayControls::onPosition(double seconds)
{
    m_position = seconds;
    if (!m_timeline->isSliderDown()) {
        const QSignalBlocker block(m_timeline);
        m_timeline->setValue(int(seconds * 1000));
    }
    updateLabel();
}

void ReplayControls::onPlaying(bool playing)
{
    m_playing = playing;
    m_play->setText(playing ? tr("Pause") : tr("Play"));
}

void ReplayControls::seekToSlider()
{
    if (m_session)
        m_session->seek(double(m_timeline->value()) / 1000.0);
}

void ReplayControls::updateLabel()
{
    m_time->setText(m_deviceClock ? tr("%1 / %2 (device clock)").arg(clock(m_position), clock(m_duration))
                                  : tr("%1 / %2").arg(clock(m_position), clock(m_duration)));
}

} // namespace imudesk::ui
