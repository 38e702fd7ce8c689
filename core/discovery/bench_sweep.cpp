#include "discovery/bench_sweep.h"

#include "device/can_session.h"
#include "device/hec495_family.h"
#include "device/modbus_session.h"
#include "io/can_transport.h"
#include "io/serial_transport.h"
#include "links/link_opener.h"
#include "links/serial_family.h"
#include "protocol/can/can_setting_catalog.h"
#include "protocol/modbus/hipnuc_writes.h"

#include <QCanBus>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QPointer>
#include <QSerialPortInfo>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

Q_LOGGING_CATEGORY(lcSweep, "imudesk.core.discovery", QtInfoMsg)

namespace imudesk::discovery {

namespace {

// The ids a Modbus device of the built-in families answers at from the factory: a HiPNUC
// module 80, an HEC495 1 (ModbusOptions::effectiveNodeId).
const int kLikelyIds[] = {80, 1};
// How long a fast probe waits beyond the wire time of its request and the answer: a late answer
// is not lost, its id is asked again slowly (ModbusFamily::noteLateAnswer).
constexpr int kFastSlackMs = 8;
// How long a found serial device may take to say who it is.
constexpr int kIdentifyMs = 4000;

int fastTimeoutMs(int baud)
{
    // 8 bytes out, 9 back (a two-register read), 11 bits each, half as much again for the gaps.
    return int(std::ceil(1.5 * 17.0 * 11.0 * 1000.0 / std::max(1, baud))) + kFastSlackMs;
}

} // namespace

// ---------------------------------------------------------------------------------------
// What a probe of one port or bus reports to the sweep, and what it found.
struct SweepSink {
    std::function<void(const QString &)> progress;
    std::function<void(const FoundDevice &)> found;
    std::function<void(const Conflict &)> conflict;
    std::function<void()> done;
};

class SweepProbe : public QObject {
public:
    explicit SweepProbe(SweepSink sink) : m_sink(std::move(sink)) {}
    bool finished() const { return m_finished; }
    QList<FoundDevice> devices;
    QList<Conflict> conflicts;
    QList<PortNote> notes;

protected:
    void addDevice(const FoundDevice &d)
    {
        devices.append(d);
        m_sink.found(d);
    }
    void addConflict(const Conflict &c)
    {
        conflicts.append(c);
        m_sink.conflict(c);
    }
    void progress(const QString &detail) { m_sink.progress(detail); }
    // The probe ended by itself: the sweep hears of it.
    void end()
    {
        if (m_finished)
            return;
        m_finished = true;
        m_sink.done();
    }

    SweepSink m_sink;
    bool m_finished = false;
};

// ---------------------------------------------------------------------------------------
// One serial port: the serial families, then Modbus RTU.

class PortSweep : public SweepProbe {
public:
    PortSweep(QString port, const SweepOptions &options, SweepSink sink)
        : SweepProbe(std::move(sink)), m_port(std::move(port)), m_options(options)
    {
        m_identifyTimer.setSingleShot(true);
        connect(&m_identifyTimer, &QTimer::timeout, this, [this] { finishSerial(); });
    }
    ~PortSweep() override { stop(); }

    double fraction() const { return m_finished ? 1.0 : m_fraction; }

    void start()
    {
        connect(&m_opener, &device::LinkOpener::detecting, this, [this](const QString &detail) {
            ++m_ratesTried;
            const double rates = double(std::max<size_t>(1, device::serialDetectionBauds().size()));
            m_fraction = std::min(0.3, 0.3 * m_ratesTried / rates);
            progress(detail);
        });
        connect(&m_opener, &device::LinkOpener::ready, this, [this] { serialFound(); });
        connect(&m_opener, &device::LinkOpener::failed, this, [this](const QString &why) { serialFailed(why); });
        if (!m_options.serialFamilies) {
            startModbus();
            return;
        }
        device::LinkRequest r = device::LinkRequest::serial(m_port);
        r.autoReconnect = false;
        progress(BenchSweep::tr("looking for a serial device"));
        m_opener.open(r);
    }

    // Ends what runs now; why: the note for a port where nothing was found yet.
    void stop(PortNote::Kind why = PortNote::Kind::Cancelled)
    {
        if (m_finished)
            return;
        m_opener.cancel();
        if (m_link.link) {
            // Found, its identity not read yet: listed with what the detection told.
            finishSerial(true);
            return;
        }
        m_identifyTimer.stop();
        if (m_modbus) {
            m_modbus->disconnect(this);
            m_modbus->close();
            m_modbus.reset();
            if (m_modbusTotal > 0 && devices.isEmpty())
                notes.append({m_port, why,
                              why == PortNote::Kind::OutOfTime
                                  ? BenchSweep::tr("no serial device answered; as a Modbus line %1 of %2 addresses and rates were "
                                       "asked before the time was up (nothing answered): give the sweep more time")
                                        .arg(m_modbusDone)
                                        .arg(m_modbusTotal)
                                  : BenchSweep::tr("the sweep was cancelled while the port was asked as a Modbus line")});
        } else if (devices.isEmpty() && notes.isEmpty()) {
            notes.append({m_port, why,
                          why == PortNote::Kind::OutOfTime ? BenchSweep::tr("the time was up before anything answered")
                                                           : BenchSweep::tr("the sweep was cancelled")});
        }
        m_finished = true;
    }

private:
    void serialFound()
    {
        m_fraction = 0.3;
        const device::LinkRequest &r = m_opener.request();
        m_family = r.family;
        m_baud = r.baud;
        m_address = r.deviceAddress;
        m_link = m_opener.take();
        if (!m_link.link) {
            finishSerial();
            return;
        }
        if (const auto *kind = device::serialFamily(m_family))
            progress(BenchSweep::tr("%1 at %2 baud: reading its identity").arg(kind->displayName()).arg(m_baud));
        connect(m_link.link.get(), &device::DeviceLink::identityChanged, this, [this](const model::DeviceIdentity &id) {
            m_identity = id;
            if (id.usable())
                QTimer::singleShot(0, this, [this] { finishSerial(); }); // not inside the link's signal
        });
        m_identifyTimer.start(kIdentifyMs);
        m_link.start();
    }

    // cutShort: the sweep ended before the device said who it is.
    void finishSerial(bool cutShort = false)
    {
        if (m_finished)
            return;
        m_identifyTimer.stop();
        FoundDevice d;
        d.link = FoundDevice::Link::Serial;
        d.port = m_port;
        d.baud = m_baud;
        d.family = m_family;
        d.model = QString::fromStdString(m_identity.productName);
        d.serial = QString::fromStdString(m_identity.serial);
        if (m_identity.firmware)
            d.firmware = QString::fromStdString(m_identity.firmware->toString());
        if (m_identity.busAddress >= 0)
            d.address = m_identity.busAddress;
        else if (m_family == QLatin1String("hec495") && m_address >= 0)
            d.address = m_address;
        if (!m_identity.usable())
            d.note = cutShort ? BenchSweep::tr("the sweep ended before it said who it is")
                              : BenchSweep::tr("it streams, but did not say who it is within %1 s").arg(kIdentifyMs / 1000);
        if (m_link.link) {
            m_link.link->disconnect(this);
            m_link.link->close();
            m_link = {};
        }
        addDevice(d);
        end();
    }

    void serialFailed(const QString &why)
    {
        using io::OpenErrorKind;
        const QString busy = io::SerialTransport::describeOpenError(m_port, OpenErrorKind::Busy, {});
        const QString denied = io::SerialTransport::describeOpenError(m_port, OpenErrorKind::Permission, {});
        const QString missing = io::SerialTransport::describeOpenError(m_port, OpenErrorKind::NotFound, {});
        if (why == busy || why == denied || why == missing) {
            notes.append({m_port,
                          why == busy     ? PortNote::Kind::Busy
                          : why == denied ? PortNote::Kind::NoPermission
                                          : PortNote::Kind::Failed,
                          why});
            end();
            return;
        }
        m_heard = m_opener.bytesHeard();
        if (!m_options.modbus) {
            noteNothing();
            end();
            return;
        }
        startModbus();
    }

    void startModbus()
    {
        int likely = 0;
        const auto plan = BenchSweep::modbusPlan(&likely);
        device::ModbusScanOptions scan;
        scan.oneRate = true;
        for (int i = 0; i < plan.size(); ++i) {
            const auto &[baud, id] = plan.at(i);
            // The likely ids wait as long as a careful scan; the rest are fast (a late answer is
            // asked again).
            scan.plan.append({baud, id, i < likely ? 0 : fastTimeoutMs(baud)});
        }
        m_modbusTotal = int(plan.size());
        device::ModbusOptions o;
        o.port = m_port;
        o.baud = plan.front().first;
        o.pollHz = 0;
        o.identify = false;
        o.retries = 0;
        m_modbus = std::make_unique<device::ModbusSession>();
        m_modbus->setAutoReconnect(false);
        connect(m_modbus.get(), &device::DeviceLink::stateChanged, this,
                [this, scan](device::SessionState s, const QString &detail) {
                    if (s == device::SessionState::Connected && !m_scanStarted) {
                        m_scanStarted = true;
                        progress(BenchSweep::tr("asking it as a Modbus RTU line"));
                        m_modbus->scan(scan);
                    } else if (s == device::SessionState::Failed && !m_scanStarted) {
                        notes.append({m_port, PortNote::Kind::Failed, detail});
                        QTimer::singleShot(0, this, [this] { closeModbus(); });
                    }
                });
        connect(m_modbus.get(), &device::ModbusSession::scanProgress, this, [this](int done, int total) {
            m_modbusDone = done;
            m_fraction = 0.3 + 0.7 * double(done) / std::max(1, total);
        });
        connect(m_modbus.get(), &device::ModbusSession::scanFound, this, [this](const device::ModbusScanHit &hit) {
            FoundDevice d;
            d.link = FoundDevice::Link::Modbus;
            d.port = m_port;
            d.baud = hit.baud;
            d.address = hit.nodeId;
            d.model = QString::fromStdString(hit.identity.productName);
            d.serial = QString::fromStdString(hit.identity.serial);
            if (hit.identity.firmware)
                d.firmware = QString::fromStdString(hit.identity.firmware->toString());
            // A HiPNUC module answers the probe with its UART1_BAUD code and its own id (MD_ID);
            // an HEC495 with its pitch there (a float) and no identity block.
            const bool hipnucLike = hit.probeValues.size() == 2 && hit.probeValues.at(1) == hit.nodeId
                && hit.probeValues.at(0) <= 8;
            if (hit.identified) {
                d.family = QStringLiteral("hipnuc-modbus");
            } else if (!hit.exception && !hipnucLike) {
                d.family = QStringLiteral("hec495-modbus");
                d.model = QStringLiteral("HEC495");
                d.note = BenchSweep::tr("known by its answer at the angle registers (no identity block)");
            } else {
                d.family = QStringLiteral("modbus");
                d.note = hit.summary;
            }
            if (hit.damaged > 0) {
                Conflict c;
                c.port = m_port;
                c.link = QStringLiteral("modbus");
                c.address = hit.nodeId;
                c.evidence = BenchSweep::tr("%1 replies to id %2 failed their CRC while other ids' replies were whole: two "
                                "devices answering at once garble each other")
                                 .arg(hit.damaged)
                                 .arg(hit.nodeId);
                c.advice = BenchSweep::tr("Connect the devices one at a time and give each its own Modbus id (Settings, MD_ID; "
                              "save and reset), then sweep again.");
                addConflict(c);
            }
            progress(BenchSweep::tr("Modbus id %1 answers at %2 baud").arg(hit.nodeId).arg(hit.baud));
            addDevice(d);
        });
        connect(m_modbus.get(), &device::ModbusSession::scanFinished, this,
                [this](const QList<device::ModbusScanHit> &, bool) {
                    QTimer::singleShot(0, this, [this] { closeModbus(); });
                });
        m_modbus->open(o);
    }

    void closeModbus()
    {
        if (m_finished)
            return;
        if (m_modbus) {
            m_modbus->disconnect(this);
            m_modbus->close();
            m_modbus.reset();
        }
        if (devices.isEmpty() && notes.isEmpty())
            noteNothing();
        end();
    }

    void noteNothing()
    {
        if (m_heard > 0)
            notes.append({m_port, PortNote::Kind::Garbage,
                          BenchSweep::tr("%1 bytes arrived but none formed a frame of any family at any rate%2: check the "
                             "wiring (A/B swapped on RS-485, TX/RX), the parity and that the device is one ImuDesk "
                             "knows")
                              .arg(m_heard)
                              .arg(m_options.modbus ? BenchSweep::tr(", nor a Modbus reply") : QString())});
        else
            notes.append({m_port, PortNote::Kind::Silent,
                          BenchSweep::tr("nothing answered at any rate%1: check the power and the wiring, or that a device is "
                             "connected at all")
                              .arg(m_options.modbus ? BenchSweep::tr(" (serial families and Modbus ids 1-247)") : QString())});
    }

    QString m_port;
    SweepOptions m_options;
    device::LinkOpener m_opener;
    device::OpenedLink m_link;
    std::unique_ptr<device::ModbusSession> m_modbus;
    QTimer m_identifyTimer;
    model::DeviceIdentity m_identity;
    QString m_family;
    int m_baud = 0;
    int m_address = -1;
    quint64 m_heard = 0;
    int m_ratesTried = 0;
    int m_modbusDone = 0;
    int m_modbusTotal = 0;
    bool m_scanStarted = false;
    double m_fraction = 0;
};

// ---------------------------------------------------------------------------------------
// One CAN bus: listen at each bit rate, then ask at the one that showed clean traffic.

class CanSweep : public SweepProbe {
public:
    CanSweep(QString bus, const SweepOptions &options, SweepSink sink)
        : SweepProbe(std::move(sink)), m_bus(std::move(bus)), m_options(options), m_survey(m_bus)
    {
        m_timer.setSingleShot(true);
        const io::CanAddress address = io::CanAddress::parse(m_bus);
        m_plugin = address.plugin;
        m_interface = address.interfaceName;
        // Qt's virtualcan keeps no bit rate (its backend ignores the key): one listen tells all.
        if (m_plugin == QLatin1String("virtualcan"))
            m_rates = {0};
        else
            m_rates = options.canBitrates.isEmpty() ? BenchSweep::canBitratesToTry() : options.canBitrates;
    }
    ~CanSweep() override { stop(); }

    double fraction() const
    {
        if (m_finished)
            return 1.0;
        if (m_asking)
            return 0.6 + 0.4 * double(m_question) / std::max<size_t>(1, m_questions.size());
        return 0.6 * double(m_rateIndex) / std::max<qsizetype>(1, m_rates.size());
    }

    void start() { listenAt(0); }

    void stop(PortNote::Kind why = PortNote::Kind::Cancelled)
    {
        if (m_finished)
            return;
        m_timer.stop();
        closeSession();
        if (m_asking)
            collect(); // what the questions so far showed
        if (devices.isEmpty() && notes.isEmpty())
            notes.append({m_bus, why,
                          why == PortNote::Kind::OutOfTime ? BenchSweep::tr("the time was up before the bus was heard at every bit rate")
                                                           : BenchSweep::tr("the sweep was cancelled")});
        m_finished = true;
    }

private:
    void openSession(int bitrate)
    {
        device::CanSessionOptions o;
        o.plugin = m_plugin;
        o.interfaceName = m_interface;
        o.bitrate = bitrate;
        m_session = std::make_unique<device::CanSession>();
        m_session->setAutoReconnect(false);
        m_errors = 0;
        connect(m_session.get(), &device::CanSession::framesSeen, this, [this](const device::CanFrameEvents &events) {
            for (const auto &e : events) {
                if (e.transmitted)
                    continue;
                if (m_asking && m_question < m_questions.size())
                    m_survey.answered(m_questions[m_question], e.frame);
                else if (!m_asking)
                    m_survey.heard(e.frame);
            }
        });
        connect(m_session.get(), &device::DeviceLink::errorOccurred, this, [this](const QString &) { ++m_errors; });
        connect(m_session.get(), &device::DeviceLink::streamWarning, this, [this](const QString &w) {
            if (!w.isEmpty())
                ++m_errors;
        });
        connect(m_session.get(), &device::DeviceLink::stateChanged, this,
                [this](device::SessionState s, const QString &detail) {
                    if (s == device::SessionState::Failed) {
                        m_openError = detail;
                        ++m_errors;
                    }
                });
        m_session->open(o);
    }

    void closeSession()
    {
        if (!m_session)
            return;
        m_session->disconnect(this);
        m_session->close();
        m_session.reset();
    }

    QString rateText(int rate) const { return rate > 0 ? BenchSweep::tr("%1 bit/s").arg(rate) : BenchSweep::tr("the interface's rate"); }

    void listenAt(qsizetype i)
    {
        m_rateIndex = i;
        if (i >= m_rates.size()) {
            // No rate showed clean traffic. A silent bus with no errors at the first rate is asked
            // there (its nodes may be polled only); a bus with errors everywhere is not asked at all.
            if (m_quietRate >= 0) {
                m_rate = m_quietRate;
                openSession(m_rate);
                QTimer::singleShot(100, this, [this] { ask(); });
                return;
            }
            notes.append({m_bus, m_openError.isEmpty() ? PortNote::Kind::Garbage : PortNote::Kind::Failed,
                          m_openError.isEmpty()
                              ? BenchSweep::tr("errors at every bit rate tried (%1): check the termination (120 Ω at each end), "
                                   "CAN-H/CAN-L and the ground; nothing was sent on this bus")
                                    .arg(ratesText())
                              : m_openError});
            end();
            return;
        }
        m_rate = m_rates.at(i);
        progress(BenchSweep::tr("listening at %1").arg(rateText(m_rate)));
        m_survey = CanSurvey(m_bus);
        openSession(m_rate);
        m_timer.disconnect();
        connect(&m_timer, &QTimer::timeout, this, [this] { listened(); });
        m_timer.start(m_options.canListenMs);
    }

    QString ratesText() const
    {
        QStringList r;
        for (int x : m_rates)
            r << QString::number(x);
        return r.join(QLatin1Char('/'));
    }

    void listened()
    {
        const bool clean = m_errors == 0;
        qCDebug(lcSweep) << m_bus << m_rate << "frames" << m_survey.framesHeard() << "errors" << m_errors;
        if (clean && m_survey.framesHeard() > 0) {
            ask();
            return;
        }
        if (clean && m_quietRate < 0 && m_openError.isEmpty())
            m_quietRate = m_rate;
        closeSession();
        listenAt(m_rateIndex + 1);
    }

    void ask()
    {
        m_asking = true;
        m_questions = m_survey.questions();
        m_question = 0;
        progress(BenchSweep::tr("asking the nodes at %1").arg(rateText(m_rate)));
        askNext();
    }

    void askNext()
    {
        if (m_question >= m_questions.size()) {
            collect();
            closeSession();
            end();
            return;
        }
        if (!m_session) {
            end();
            return;
        }
        m_session->sendFrame(m_questions[m_question].frame);
        m_timer.disconnect();
        connect(&m_timer, &QTimer::timeout, this, [this] {
            m_survey.closeQuestion(m_questions[m_question]);
            ++m_question;
            askNext();
        });
        m_timer.start(m_options.canAnswerMs);
    }

    void collect()
    {
        if (m_collected)
            return;
        m_collected = true;
        const QString why = m_rate > 0 ? QString() : BenchSweep::tr("Qt's virtualcan interface has no bit rate");
        QList<FoundDevice> found;
        QList<Conflict> shown;
        m_survey.collect(m_rate, why, &found, &shown);
        for (const Conflict &c : shown)
            addConflict(c);
        for (const FoundDevice &d : found)
            addDevice(d);
        if (devices.isEmpty())
            notes.append({m_bus, PortNote::Kind::Silent,
                          m_survey.framesHeard() > 0
                              ? BenchSweep::tr("%1 frames at %2, none of a device ImuDesk knows, and nothing answered")
                                    .arg(m_survey.framesHeard())
                                    .arg(rateText(m_rate))
                              : BenchSweep::tr("no traffic at any bit rate (%1) and nothing answered when asked at %2: check the "
                                   "power and the wiring")
                                    .arg(ratesText(), rateText(m_rate))});
    }

    QString m_bus, m_plugin, m_interface;
    SweepOptions m_options;
    CanSurvey m_survey;
    std::unique_ptr<device::CanSession> m_session;
    QTimer m_timer;
    QList<int> m_rates;
    qsizetype m_rateIndex = 0;
    int m_rate = 0;
    int m_quietRate = -1;
    int m_errors = 0;
    QString m_openError;
    bool m_asking = false;
    bool m_collected = false;
    std::vector<CanSurvey::Question> m_questions;
    size_t m_question = 0;
};

// ---------------------------------------------------------------------------------------

BenchSweep::BenchSweep(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<FoundDevice>();
    qRegisterMetaType<Conflict>();
    m_budget.setSingleShot(true);
    connect(&m_budget, &QTimer::timeout, this, [this] {
        for (auto &p : m_ports)
            p->stop(PortNote::Kind::OutOfTime);
        for (auto &b : m_buses)
            b->stop(PortNote::Kind::OutOfTime);
        finish(false);
    });
}

BenchSweep::~BenchSweep()
{
    m_budget.stop();
    m_ports.clear();
    m_buses.clear();
}

QStringList BenchSweep::serialPortsOf(const SweepOptions &options)
{
    QStringList ports;
    if (options.machinePorts)
        for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
            ports << info.systemLocation();
    for (const QString &p : options.ports)
        if (!p.isEmpty() && !ports.contains(io::SerialTransport::systemLocation(p)))
            ports << io::SerialTransport::systemLocation(p);
    return ports;
}

QStringList BenchSweep::canBusesOf(const SweepOptions &options)
{
    QStringList buses;
    if (options.machineCan && QCanBus::instance()->plugins().contains(QStringLiteral("socketcan")))
        for (const auto &info : QCanBus::instance()->availableDevices(QStringLiteral("socketcan")))
            buses << QStringLiteral("socketcan:") + info.name();
    for (const QString &b : options.canBuses)
        if (!b.isEmpty() && !buses.contains(b))
            buses << b;
    return buses;
}

QList<int> BenchSweep::canBitratesToTry()
{
    namespace can = protocol::can;
    // The factory rates first (HiPNUC 500K, HEC495 250K), then every documented rate, fastest first.
    QList<int> rates{can::canBitrates(can::CanProtocol::J1939).factory, can::canBitrates(can::CanProtocol::Hec495).factory};
    std::set<int, std::greater<>> rest;
    for (auto p : {can::CanProtocol::J1939, can::CanProtocol::CanOpen, can::CanProtocol::Hec495})
        for (int r : can::canBitrates(p).rates)
            rest.insert(r);
    for (int r : rest)
        if (!rates.contains(r))
            rates << r;
    return rates;
}

QList<std::pair<int, int>> BenchSweep::modbusPlan(int *likelyCount)
{
    std::vector<int> bauds = protocol::modbus::HipnucWrites::bauds();
    for (int b : device::Hec495Family::detectionBauds())
        if (std::find(bauds.begin(), bauds.end(), b) == bauds.end())
            bauds.push_back(b);
    // The factory rates first, then the rest fastest first (a fast rate asks 247 ids in a few seconds).
    std::vector<int> ordered{115200, 9600};
    std::vector<int> rest;
    for (int b : bauds)
        if (std::find(ordered.begin(), ordered.end(), b) == ordered.end())
            rest.push_back(b);
    std::sort(rest.begin(), rest.end(), std::greater<>());
    ordered.insert(ordered.end(), rest.begin(), rest.end());
    QList<std::pair<int, int>> plan;
    for (int b : ordered)
        for (int id : kLikelyIds)
            plan.append({b, id});
    if (likelyCount)
        *likelyCount = int(plan.size());
    std::vector<int> fastest = ordered;
    std::sort(fastest.begin(), fastest.end(), std::greater<>());
    for (int b : fastest)
        for (int id = 1; id <= 247; ++id)
            if (std::find(std::begin(kLikelyIds), std::end(kLikelyIds), id) == std::end(kLikelyIds))
                plan.append({b, id});
    return plan;
}

SweepSink BenchSweep::sinkFor(const QString &port)
{
    return SweepSink{[this, port](const QString &d) { publishProgress(port, d); },
                     [this](const FoundDevice &d) { Q_EMIT deviceFound(d); },
                     [this](const Conflict &c) { Q_EMIT conflictFound(c); }, [this] { probeDone(); }};
}

void BenchSweep::start(const SweepOptions &options)
{
    cancel();
    m_options = options;
    m_result = {};
    m_ports.clear();
    m_buses.clear();
    m_running = true;
    m_clock.start();
    for (const QString &port : serialPortsOf(options)) {
        auto p = std::make_unique<PortSweep>(port, options, sinkFor(port));
        m_ports.push_back(std::move(p));
    }
    for (const QString &bus : canBusesOf(options)) {
        auto b = std::make_unique<CanSweep>(bus, options, sinkFor(bus));
        m_buses.push_back(std::move(b));
    }
    if (m_ports.empty() && m_buses.empty()) {
        QTimer::singleShot(0, this, [this] { finish(false); });
        return;
    }
    m_budget.start(std::max(1000, options.budgetMs));
    for (auto &p : m_ports)
        p->start();
    for (auto &b : m_buses)
        b->start();
}

void BenchSweep::cancel()
{
    if (!m_running)
        return;
    for (auto &p : m_ports)
        p->stop(PortNote::Kind::Cancelled);
    for (auto &b : m_buses)
        b->stop(PortNote::Kind::Cancelled);
    finish(true);
}

void BenchSweep::publishProgress(const QString &port, const QString &detail)
{
    double sum = 0;
    for (auto &p : m_ports)
        sum += p->fraction();
    for (auto &b : m_buses)
        sum += b->fraction();
    const double n = double(std::max<size_t>(1, m_ports.size() + m_buses.size()));
    Q_EMIT progress(int(1000 * sum / n), 1000, port, detail);
}

void BenchSweep::probeDone()
{
    // Later: a probe calls this from its own signal.
    QTimer::singleShot(0, this, [this] {
        if (!m_running)
            return;
        publishProgress({}, {});
        const bool all = std::all_of(m_ports.begin(), m_ports.end(), [](auto &p) { return p->finished(); })
            && std::all_of(m_buses.begin(), m_buses.end(), [](auto &b) { return b->finished(); });
        if (all)
            finish(false);
    });
}

void BenchSweep::finish(bool cancelled)
{
    if (!m_running)
        return;
    m_running = false;
    m_budget.stop();
    m_result.seconds = m_clock.elapsed() / 1000.0;
    m_result.cancelled = cancelled;
    for (auto &p : m_ports) {
        m_result.devices += p->devices;
        m_result.conflicts += p->conflicts;
        m_result.notes += p->notes;
    }
    for (auto &b : m_buses) {
        m_result.devices += b->devices;
        m_result.conflicts += b->conflicts;
        m_result.notes += b->notes;
    }
    Q_EMIT progress(1000, 1000, {}, {});
    Q_EMIT finished();
}

} // namespace imudesk::discovery
