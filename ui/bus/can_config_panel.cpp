#include "bus/can_config_panel.h"

#include "bus/can_settings_table.h"
#include "device/can_session.h"
#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

namespace imudesk::ui {

using protocol::can::CanProtocol;
namespace j1939 = protocol::can::j1939;
namespace canopen = protocol::can::canopen;

CanConfigPanel::CanConfigPanel(QWidget *parent)
    : QWidget(parent), m_protocol(new QLabel(this)), m_output(new QComboBox(this)), m_period(new QSpinBox(this)),
      m_applyPeriod(new QPushButton(tr("Apply"), this)), m_syncMode(new QCheckBox(tr("SYNC mode (TPDO sent on each SYNC)"), this)),
      m_sendSync(new QPushButton(tr("Send SYNC"), this)), m_syncPeriod(new QSpinBox(this)), m_heartbeat(new QSpinBox(this)),
      m_applyHeartbeat(new QPushButton(tr("Apply"), this)), m_node(new QSpinBox(this)), m_applyNode(new QPushButton(tr("Apply"), this)),
      m_bitrate(new QComboBox(this)), m_applyBitrate(new QPushButton(tr("Apply"), this)), m_attitude(new QComboBox(this)),
      m_applyAttitude(new QPushButton(tr("Apply"), this)), m_outputOn(new QPushButton(tr("Output on"), this)),
      m_outputOff(new QPushButton(tr("Output off"), this)), m_trigger(new QPushButton(tr("Trigger once"), this)),
      m_inclX(new QCheckBox(tr("X reversed"), this)), m_inclY(new QCheckBox(tr("Y reversed"), this)),
      m_applyIncl(new QPushButton(tr("Apply"), this)), m_pdoMode(new QComboBox(this)), m_workMode(new QComboBox(this)),
      m_applyModes(new QPushButton(tr("Apply"), this)), m_allOn(new QPushButton(tr("All nodes on"), this)),
      m_allOff(new QPushButton(tr("All nodes off"), this)), m_save(new QPushButton(tr("Save"), this)),
      m_reset(new QPushButton(tr("Reset"), this)), m_factory(new QPushButton(tr("Factory defaults…"), this)),
      m_scan(new QPushButton(tr("Scan nodes 1–127"), this)), m_cancelScan(new QPushButton(tr("Cancel"), this)),
      m_scanProgress(new QProgressBar(this)), m_log(new QPlainTextEdit(this))
{
    m_period->setRange(0, 65535);
    m_period->setSuffix(tr(" ms"));
    m_period->setValue(10);
    m_syncPeriod->setRange(0, 10000);
    m_syncPeriod->setSuffix(tr(" ms"));
    m_syncPeriod->setSpecialValueText(tr("periodic SYNC off"));
    m_heartbeat->setRange(0, 65535);
    m_heartbeat->setSuffix(tr(" ms"));
    m_node->setRange(1, 127);
    m_attitude->addItem(tr("Heading reset (J1939 1)"), 1);
    m_attitude->addItem(tr("Set relative zero (2)"), 2);
    m_attitude->addItem(tr("Auto level (J1939 3)"), 3);
    m_attitude->addItem(tr("Clear zero (5)"), 5);
    m_trigger->setToolTip(tr("J1939 register 0x96: the module sends the chosen PGN once (no reply; the frame is the answer)"));
    m_inclX->setToolTip(tr("Inclinometer X axis direction: J1939 register 0x9E, CANopen object 0x209E (0 default, 1 reversed)"));
    m_inclY->setToolTip(tr("Inclinometer Y axis direction: J1939 register 0x9F, CANopen object 0x209F (0 default, 1 reversed)"));
    m_workMode->addItem(tr("Angles, acc., rate (0x02)"), 0x02);
    m_workMode->addItem(tr("Rate at 500 Hz (0x0A)"), 0x0A);
    m_workMode->setToolTip(tr("HEC495 work mode, object 0x6245: 0x02 pitch, roll, acceleration and rate (default); "
                              "0x0A rate at 500 Hz"));
    m_pdoMode->setToolTip(tr("HEC495 PDO mode, object 0x1080"));
    m_allOn->setToolTip(tr("NMT start to node 0: every node on the bus starts its PDOs (HEC495: not saved)"));
    m_allOff->setToolTip(tr("NMT stop to node 0: every node on the bus stops its PDOs (HEC495: not saved)"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(500);
    m_cancelScan->setEnabled(false);

    auto row = [this](QWidget *a, QWidget *b = nullptr, QWidget *c = nullptr) {
        auto *w = new QWidget(this);
        auto *h = new QHBoxLayout(w);
        h->setContentsMargins(0, 0, 0, 0);
        for (QWidget *x : {a, b, c})
            if (x)
                h->addWidget(x);
        return w;
    };
    auto *form = new QFormLayout;
    form->addRow(tr("Protocol:"), m_protocol);
    form->addRow(tr("Output period:"), row(m_output, m_period, m_applyPeriod));
    form->addRow(QString(), m_trigger);
    form->addRow(QString(), m_syncMode);
    form->addRow(tr("SYNC:"), row(m_sendSync, m_syncPeriod));
    form->addRow(tr("Heartbeat:"), row(m_heartbeat, m_applyHeartbeat));
    form->addRow(tr("Node ID:"), row(m_node, m_applyNode));
    form->addRow(tr("CAN bit rate:"), row(m_bitrate, m_applyBitrate));
    form->addRow(tr("Attitude:"), row(m_attitude, m_applyAttitude));
    form->addRow(tr("Inclinometer:"), row(m_inclX, m_inclY, m_applyIncl));
    form->addRow(tr("HEC495 PDO:"), m_pdoMode);
    form->addRow(tr("Work mode:"), row(m_workMode, m_applyModes));
    form->addRow(tr("Output:"), row(m_outputOn, m_outputOff));
    form->addRow(tr("Every node:"), row(m_allOn, m_allOff));
    form->addRow(tr("Settings:"), row(m_save, m_reset, m_factory));
    form->addRow(tr("Discovery:"), row(m_scan, m_scanProgress, m_cancelScan));
    // Two pages: every setting with the module's value beside the new one (each row says what
    // its write found), and the actions (output, SYNC, attitude, save, scan) with their log.
    m_settings = new CanSettingsTable(this);
    m_settings->setObjectName(QStringLiteral("canSettings"));
    auto *actions = new QWidget(this);
    auto *actionsLayout = new QVBoxLayout(actions);
    actionsLayout->addLayout(form);
    actionsLayout->addWidget(m_log, 1);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("canConfigTabs"));
    m_tabs->setDocumentMode(true);
    m_tabs->addTab(m_settings, tr("Settings"));
    m_tabs->addTab(actions, tr("Actions"));
    // The dock's height is the page on show's, not the tallest page's: a hidden page asks for
    // no room (QStackedLayout honours an ignored size policy).
    auto sizeToCurrent = [this](int current) {
        for (int i = 0; i < m_tabs->count(); ++i) {
            const auto policy = i == current ? QSizePolicy::Preferred : QSizePolicy::Ignored;
            m_tabs->widget(i)->setSizePolicy(policy, policy);
        }
    };
    connect(m_tabs, &QTabWidget::currentChanged, this, sizeToCurrent);
    sizeToCurrent(m_tabs->currentIndex());
    auto *lay = new QVBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->addWidget(m_tabs);

    connect(m_applyPeriod, &QPushButton::clicked, this, &CanConfigPanel::applyPeriod);
    connect(m_syncMode, &QCheckBox::clicked, this, [this](bool on) {
        if (m_session)
            track(m_session->setSyncMode(m_output->currentData().toInt(), on), on ? tr("SYNC mode on") : tr("SYNC mode off"));
    });
    connect(m_sendSync, &QPushButton::clicked, this, [this] {
        if (m_session)
            m_session->sendSync();
    });
    connect(m_syncPeriod, &QSpinBox::valueChanged, this, [this](int ms) {
        if (m_session)
            m_session->setSyncPeriod(ms);
    });
    connect(m_applyHeartbeat, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->setHeartbeat(m_heartbeat->value()), tr("heartbeat"));
    });
    connect(m_applyNode, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->setNodeId(m_node->value()), tr("node ID %1").arg(m_node->value()));
    });
    connect(m_applyBitrate, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->setBitrate(m_bitrate->currentData().toInt()), tr("bit rate"));
    });
    connect(m_applyAttitude, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->attitudeReset(m_attitude->currentData().toInt()), m_attitude->currentText());
    });
    connect(m_outputOn, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->setOutputEnabled(true), tr("output on"));
    });
    connect(m_outputOff, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->setOutputEnabled(false), tr("output off"));
    });
    connect(m_trigger, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->trigger(m_output->currentData().toUInt()), tr("trigger %1 once").arg(m_output->currentText()));
    });
    connect(m_applyIncl, &QPushButton::clicked, this, [this] {
        if (!m_session)
            return;
        track(m_session->setInclinometerSign(0, m_inclX->isChecked()),
              m_inclX->isChecked() ? tr("inclinometer X reversed") : tr("inclinometer X default"));
        track(m_session->setInclinometerSign(1, m_inclY->isChecked()),
              m_inclY->isChecked() ? tr("inclinometer Y reversed") : tr("inclinometer Y default"));
    });
    connect(m_applyModes, &QPushButton::clicked, this, [this] {
        if (!m_session)
            return;
        track(m_session->setHec495PdoMode(m_pdoMode->currentData().toInt()), m_pdoMode->currentText());
        if (m_workMode->isEnabled())
            track(m_session->setHec495WorkMode(m_workMode->currentData().toInt()), m_workMode->currentText());
    });
    connect(m_allOn, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->setAllNodesOutput(true), tr("every node on"));
    });
    connect(m_allOff, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->setAllNodesOutput(false), tr("every node off"));
    });
    connect(m_save, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->save(), tr("save"));
    });
    connect(m_reset, &QPushButton::clicked, this, [this] {
        if (m_session)
            track(m_session->reset(), tr("reset"));
    });
    connect(m_factory, &QPushButton::clicked, this, [this] {
        if (!m_session)
            return;
        if (QMessageBox::question(this, tr("Factory defaults"),
                                  tr("Restore the module's default user settings? It saves and resets itself.")) != QMessageBox::Yes)
            return;
        track(m_session->factoryReset(), tr("factory defaults"));
    });
    connect(m_scan, &QPushButton::clicked, this, [this] {
        if (!m_session)
            return;
        m_scanProgress->setRange(0, 127);
        m_scanProgress->setValue(0);
        m_scan->setEnabled(false);
        m_cancelScan->setEnabled(true);
        m_session->scanNodes(1, 127);
    });
    connect(m_cancelScan, &QPushButton::clicked, this, [this] {
        if (m_session)
            m_session->cancelScan();
    });
    connect(m_output, &QComboBox::currentIndexChanged, this, [this] { m_syncMode->setChecked(false); });
    setSession(nullptr);
}

void CanConfigPanel::setSession(device::CanSession *session)
{
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_pending.clear();
    m_session = session;
    m_settings->setSession(session);
    if (session) {
        m_connections << connect(session, &device::CanSession::requestFinished, this, &CanConfigPanel::onResult);
        m_connections << connect(session, &device::CanSession::protocolDetected, this, &CanConfigPanel::refreshForProtocol);
        // A protocol given when opening (not detected) counts from the connection on.
        m_connections << connect(session, &device::CanSession::stateChanged, this, [this] { refreshForProtocol(); });
        m_connections << connect(session, &device::CanSession::targetNodeChanged, this, [this](int n) {
            if (n >= 1 && n <= 127)
                m_node->setValue(n);
        });
        m_connections << connect(session, &device::CanSession::scanProgress, this, [this](int done, int total) {
            m_scanProgress->setRange(0, total);
            m_scanProgress->setValue(done);
        });
        m_connections << connect(session, &device::CanSession::scanFinished, this, [this](const QList<int> &nodes, bool cancelled) {
            m_scan->setEnabled(true);
            m_cancelScan->setEnabled(false);
            QStringList ids;
            for (int n : nodes)
                ids << QString::number(n);
            m_log->appendPlainText(cancelled ? tr("Scan cancelled; nodes answering so far: %1").arg(ids.isEmpty() ? tr("none") : ids.join(QStringLiteral(", ")))
                                             : tr("Scan finished; nodes answering SDO: %1").arg(ids.isEmpty() ? tr("none") : ids.join(QStringLiteral(", "))));
        });
        m_connections << connect(session, &device::CanSession::nodeDiscovered, this, [this](const device::CanNodeInfo &i) {
            m_log->appendPlainText(tr("Node %1 (%2, %3)").arg(i.node).arg(QString::fromLatin1(protocol::can::protocolName(i.protocol)), i.seenAs));
        });
    }
    refreshForProtocol();
}

void CanConfigPanel::refreshForProtocol()
{
    const CanProtocol p = m_session ? m_session->protocol() : CanProtocol::Auto;
    const bool any = m_session != nullptr;
    const bool hip = p == CanProtocol::J1939 || p == CanProtocol::CanOpen;
    m_protocol->setText(!any ? tr("no session") : p == CanProtocol::Auto ? tr("detecting…") : m_session->linkKind());
    m_output->clear();
    if (p == CanProtocol::J1939) {
        for (uint32_t pgn : j1939::dataPgns())
            m_output->addItem(QStringLiteral("PGN %1 (%2)").arg(QString::number(pgn, 16).toUpper(), QLatin1String(j1939::pgnName(pgn))), pgn);
        m_period->setRange(j1939::kMinIntervalMs, j1939::kMaxIntervalMs);
    } else if (p == CanProtocol::CanOpen) {
        for (int c = 0; c < canopen::kTpdoCount; ++c)
            m_output->addItem(tr("TPDO%1 (%2)").arg(canopen::tpdoNumber(c)).arg(QLatin1String(canopen::tpdoContent(c))), c);
        m_period->setRange(0, 65535);
    } else if (p == CanProtocol::Hec495) {
        for (int code = 0; code <= 6; ++code)
            m_output->addItem(code ? tr("PDO %1 Hz").arg(protocol::can::hec495::rateHzFromCode(uint32_t(code))) : tr("PDO off"), code);
    }
    // Only the rates the module's setting documents (CANopen 0x209A has no 800K).
    const int rate = m_bitrate->currentData().toInt();
    m_bitrate->clear();
    for (int r : device::CanSession::moduleBitrates(p, any && m_session->options().hec495Extended))
        m_bitrate->addItem(tr("%1 kbit/s").arg(r / 1000), r);
    if (const int i = m_bitrate->findData(rate); i >= 0)
        m_bitrate->setCurrentIndex(i);
    m_period->setEnabled(hip);
    m_output->setEnabled(any && p != CanProtocol::Auto);
    m_applyPeriod->setEnabled(any && p != CanProtocol::Auto);
    m_syncMode->setEnabled(p == CanProtocol::CanOpen);
    m_sendSync->setEnabled(any);
    m_syncPeriod->setEnabled(any);
    m_heartbeat->setEnabled(p == CanProtocol::CanOpen || p == CanProtocol::Hec495);
    m_applyHeartbeat->setEnabled(m_heartbeat->isEnabled());
    for (QWidget *w : std::initializer_list<QWidget *>{m_applyNode, m_applyBitrate, m_outputOn, m_outputOff})
        w->setEnabled(any && p != CanProtocol::Auto);
    m_applyAttitude->setEnabled(hip);
    m_trigger->setEnabled(p == CanProtocol::J1939);
    for (QWidget *w : std::initializer_list<QWidget *>{m_inclX, m_inclY, m_applyIncl})
        w->setEnabled(hip);
    const bool hec = p == CanProtocol::Hec495;
    const bool extended = hec && m_session->options().hec495Extended;
    const int mode = m_pdoMode->currentData().toInt();
    m_pdoMode->clear();
    if (extended) { // the extended variant: message one (X) or both (X and Y)
        m_pdoMode->addItem(tr("X message only (0)"), 0);
        m_pdoMode->addItem(tr("X and Y messages (1)"), 1);
    } else {
        m_pdoMode->addItem(tr("Float (0)"), 0);
        m_pdoMode->addItem(tr("Fixed point (1)"), 1);
        m_pdoMode->addItem(tr("Float, 0x180/0x280 only (3)"), 3);
    }
    if (const int i = m_pdoMode->findData(mode); i >= 0)
        m_pdoMode->setCurrentIndex(i);
    m_pdoMode->setEnabled(hec);
    m_workMode->setEnabled(hec && !extended);
    m_applyModes->setEnabled(hec);
    const bool nmtAll = p == CanProtocol::CanOpen || (hec && !extended);
    m_allOn->setEnabled(nmtAll);
    m_allOff->setEnabled(nmtAll);
    for (QWidget *w : std::initializer_list<QWidget *>{m_save, m_reset, m_factory})
        w->setEnabled(hip);
    m_scan->setEnabled(any);
}

void CanConfigPanel::applyPeriod()
{
    if (!m_session)
        return;
    if (m_session->protocol() == CanProtocol::Hec495) {
        track(m_session->setHec495Rate(m_output->currentData().toInt()), m_output->currentText());
        return;
    }
    track(m_session->setOutputPeriod(m_output->currentData().toUInt(), m_period->value()),
          tr("%1 every %2 ms").arg(m_output->currentText()).arg(m_period->value()));
}

void CanConfigPanel::track(quint64 id, const QString &what)
{
    m_pending.insert(id, what);
    m_log->appendPlainText(tr("→ %1 …").arg(what));
}

void CanConfigPanel::onResult(const device::CanRequestResult &r)
{
    const auto it = m_pending.find(r.id);
    if (it == m_pending.end())
        return;
    const QString what = it.value();
    m_pending.erase(it);
    const QString line = r.ok ? tr("✓ %1: confirmed (%2)").arg(what).arg(r.value) : tr("✗ %1").arg(r.message);
    m_log->appendPlainText(line);
    Q_EMIT requestDone(r.ok, r.ok ? what : r.message);
}

} // namespace imudesk::ui
