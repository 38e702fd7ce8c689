#include "configuration/hec495_settings_panel.h"

#include "device/hec495_session.h"
#include "protocol/witlink/bcd.h"
#include "protocol/witlink/commands.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>

namespace imudesk::ui {

namespace wl = protocol::witlink;

Hec495SettingsPanel::Hec495SettingsPanel(device::Hec495Session *session, QWidget *parent)
    : QWidget(parent), m_session(session)
{
    m_declination = new QDoubleSpinBox(this);
    m_declination->setRange(-wl::kMaxDeclination, wl::kMaxDeclination);
    m_declination->setDecimals(1);
    m_declination->setSingleStep(0.1);
    m_declination->setSuffix(QStringLiteral(" °"));
    m_baud = new QComboBox(this);
    for (int b : wl::commands::supportedBauds())
        m_baud->addItem(QString::number(b), b);
    m_baud->setCurrentIndex(m_baud->findData(wl::commands::kDefaultBaud));
    m_rate = new QComboBox(this);
    for (int hz : wl::commands::supportedRates())
        m_rate->addItem(QString(), hz);
    m_content = new QComboBox(this);
    for (int c = 0; c <= int(wl::OutputContent::Nmea0183); ++c)
        m_content->addItem(QString(), c);
    m_address = new QSpinBox(this);
    m_address->setRange(0, 255);
    m_address->setValue(session ? session->address() : 0);
    m_angle = new QComboBox(this);
    for (wl::Command c : {wl::Command::ReadPitch, wl::Command::ReadRoll, wl::Command::ReadHeading, wl::Command::ReadAngles})
        m_angle->addItem(QString(), int(c));

    m_readDeclination = new QPushButton(this);
    m_setDeclination = new QPushButton(this);
    m_setBaud = new QPushButton(this);
    m_setRate = new QPushButton(this);
    m_setContent = new QPushButton(this);
    m_setAddress = new QPushButton(this);
    m_save = new QPushButton(this);
    m_reset = new QPushButton(this);
    m_readAngle = new QPushButton(this);
    m_readAddress = new QPushButton(this);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    m_declinationLabel = new QLabel(this);
    m_baudLabel = new QLabel(this);
    m_rateLabel = new QLabel(this);
    m_contentLabel = new QLabel(this);
    m_addressLabel = new QLabel(this);
    m_angleLabel = new QLabel(this);

    auto *grid = new QGridLayout(this);
    int row = 0;
    grid->addWidget(m_declinationLabel, row, 0);
    grid->addWidget(m_declination, row, 1);
    grid->addWidget(m_readDeclination, row, 2);
    grid->addWidget(m_setDeclination, row++, 3);
    const std::pair<QLabel *, std::pair<QWidget *, QPushButton *>> rows[] = {
        {m_baudLabel, {m_baud, m_setBaud}},
        {m_rateLabel, {m_rate, m_setRate}},
        {m_contentLabel, {m_content, m_setContent}},
    };
    for (const auto &[label, w] : rows) {
        grid->addWidget(label, row, 0);
        grid->addWidget(w.first, row, 1, 1, 2);
        grid->addWidget(w.second, row++, 3);
    }
    grid->addWidget(m_addressLabel, row, 0);
    grid->addWidget(m_address, row, 1);
    grid->addWidget(m_readAddress, row, 2);
    grid->addWidget(m_setAddress, row++, 3);
    grid->addWidget(m_angleLabel, row, 0);
    grid->addWidget(m_angle, row, 1, 1, 2);
    grid->addWidget(m_readAngle, row++, 3);
    grid->addWidget(m_save, row, 0, 1, 2);
    grid->addWidget(m_reset, row++, 2, 1, 2);
    grid->addWidget(m_note, row++, 0, 1, 4);
    grid->addWidget(m_status, row++, 0, 1, 4);
    grid->setRowStretch(row, 1);

    if (m_session) {
        connect(m_session, &device::Hec495Session::commandFinished, this, &Hec495SettingsPanel::onFinished);
        connect(m_session, &device::Hec495Session::baudChanged, this,
                [this](int b) { m_baud->setCurrentIndex(std::max(0, m_baud->findData(b))); });
        connect(m_session, &device::Hec495Session::addressChanged, this, [this](int a) { m_address->setValue(a); });
        connect(m_readDeclination, &QPushButton::clicked, this, [this] { track(m_session->readDeclination()); });
        connect(m_setDeclination, &QPushButton::clicked, this,
                [this] { track(m_session->setDeclination(m_declination->value())); });
        connect(m_setBaud, &QPushButton::clicked, this,
                [this] { track(m_session->setBaud(m_baud->currentData().toInt())); });
        connect(m_setRate, &QPushButton::clicked, this,
                [this] { track(m_session->setOutputRate(m_rate->currentData().toInt())); });
        connect(m_setContent, &QPushButton::clicked, this, [this] {
            track(m_session->setOutputContent(wl::OutputContent(m_content->currentData().toInt())));
        });
        connect(m_setAddress, &QPushButton::clicked, this, [this] { track(m_session->setAddress(m_address->value())); });
        connect(m_readAddress, &QPushButton::clicked, this, [this] { track(m_session->queryAddress()); });
        connect(m_readAngle, &QPushButton::clicked, this,
                [this] { track(m_session->request(wl::Command(m_angle->currentData().toInt()))); });
        connect(m_save, &QPushButton::clicked, this, [this] { track(m_session->saveSettings()); });
        connect(m_reset, &QPushButton::clicked, this, &Hec495SettingsPanel::factoryReset);
    } else {
        setEnabled(false);
    }
    retranslate();
}

QString Hec495SettingsPanel::statusText() const
{
    return m_status->text();
}

void Hec495SettingsPanel::factoryReset()
{
    if (m_confirmReset
        && QMessageBox::question(this, tr("Factory reset"),
                                 tr("Restore the factory settings (9600 baud, address 0, declination 0, "
                                    "question/answer)? The session follows the module to 9600 baud."))
            != QMessageBox::Yes)
        return;
    track(m_session->factoryReset());
}

void Hec495SettingsPanel::track(quint64 id)
{
    m_pending = id;
    m_status->setText(tr("Waiting for the module…"));
    setBusy(true);
}

void Hec495SettingsPanel::onFinished(quint64 id, const device::Hec495Result &r)
{
    if (id != m_pending)
        return;
    m_pending = 0;
    setBusy(false);
    if (r.ok()) {
        if (r.reply.kind == wl::Reply::Kind::Declination)
            m_declination->setValue(r.reply.declination);
        if (r.reply.kind == wl::Reply::Kind::Address)
            m_address->setValue(r.reply.deviceAddress);
        m_status->setText(r.message);
    } else {
        m_status->setText(tr("Failed: %1").arg(r.message));
    }
    Q_EMIT requestFinished(r);
}

void Hec495SettingsPanel::setBusy(bool busy)
{
    for (QWidget *w : std::initializer_list<QWidget *>{m_readDeclination, m_setDeclination, m_setBaud, m_setRate,
                                                       m_setContent, m_setAddress, m_readAddress, m_readAngle,
                                                       m_save, m_reset})
        w->setEnabled(!busy);
}

void Hec495SettingsPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void Hec495SettingsPanel::retranslate()
{
    m_declinationLabel->setText(tr("Magnetic declination"));
    m_baudLabel->setText(tr("Baud rate"));
    m_rateLabel->setText(tr("Output rate"));
    m_contentLabel->setText(tr("Output content"));
    m_addressLabel->setText(tr("Module address"));
    m_angleLabel->setText(tr("Single reading"));
    for (QPushButton *b : {m_readDeclination, m_readAddress, m_readAngle})
        b->setText(tr("Read"));
    m_readAddress->setToolTip(tr("Ask the module for its address (manual 2.17: sent to address 0, any module answers)."));
    m_readAngle->setToolTip(tr("Ask the module once for the chosen angle (manual 2.1 to 2.4); the answer, in degrees, "
                               "shows below."));
    const QString angles[] = {tr("Pitch"), tr("Roll"), tr("Heading"), tr("Pitch, roll and heading")};
    for (int i = 0; i < m_angle->count(); ++i)
        m_angle->setItemText(i, angles[i]);
    for (QPushButton *b : {m_setDeclination, m_setBaud, m_setRate, m_setContent, m_setAddress})
        b->setText(tr("Set"));
    m_save->setText(tr("Save settings"));
    m_reset->setText(tr("Factory reset…"));
    m_note->setText(tr("Changes apply at once and are lost at power-off unless saved."));
    for (int i = 0; i < m_rate->count(); ++i) {
        const int hz = m_rate->itemData(i).toInt();
        m_rate->setItemText(i, hz == 0 ? tr("Question/answer") : tr("%1 Hz").arg(hz));
    }
    const QString contents[] = {tr("Default (angles)"), tr("Internal data"), tr("All data (read-all record)"),
                                tr("NMEA 0183")};
    for (int i = 0; i < m_content->count(); ++i)
        m_content->setItemText(i, contents[i]);
}

} // namespace imudesk::ui
