#include "hec495_session.h"

#include "device/hec495_worker.h"
#include "protocol/witlink/bcd.h"

#include <QTimer>

namespace imudesk::device {

namespace wl = protocol::witlink;

Hec495Session::Hec495Session(QObject *parent) : DeviceLink(parent)
{
    qRegisterMetaType<Hec495Result>();
    m_thread.setObjectName(QStringLiteral("imudesk-hec495"));
    m_worker = new Hec495Worker(store(), m_rawLog);
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);

    connect(m_worker, &Hec495Worker::stateChanged, this,
            [this](SessionState s, const QString &detail) { setState(s, detail); });
    connect(m_worker, &Hec495Worker::identityChanged, this, &Hec495Session::identityChanged);
    connect(m_worker, &Hec495Worker::statsUpdated, this, &Hec495Session::statsUpdated);
    connect(m_worker, &Hec495Worker::errorOccurred, this, &Hec495Session::errorOccurred);
    connect(m_worker, &Hec495Worker::commandFinished, this, &Hec495Session::commandFinished);
    connect(m_worker, &Hec495Worker::calibrationPoint, this, &Hec495Session::calibrationPoint);
    connect(m_worker, &Hec495Worker::baudChanged, this, [this](int b) {
        m_baud = b;
        Q_EMIT baudChanged(b);
    });
    connect(m_worker, &Hec495Worker::addressChanged, this, [this](int a) {
        m_address = a;
        Q_EMIT addressChanged(a);
    });
    connect(m_worker, &Hec495Worker::streamingChanged, this, [this](bool on) {
        m_streaming = on;
        Q_EMIT streamingChanged(on);
    });
    m_thread.start();
}

Hec495Session::~Hec495Session()
{
    QMetaObject::invokeMethod(m_worker, &Hec495Worker::close, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void Hec495Session::open(const QString &portName, int baud, int address)
{
    m_address = address;
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, portName, baud, address] { w->open(portName, baud, address); },
        Qt::QueuedConnection);
}

void Hec495Session::close()
{
    QMetaObject::invokeMethod(m_worker, &Hec495Worker::close, Qt::QueuedConnection);
}

void Hec495Session::setPollingRate(int hz)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, hz] { w->setPollingRate(hz); }, Qt::QueuedConnection);
}

quint64 Hec495Session::request(wl::Command command, const QByteArray &data, int timeoutMs)
{
    const quint64 id = m_nextId++;
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, id, command, data, timeoutMs] { w->request(id, uint8_t(command), data, timeoutMs); },
        Qt::QueuedConnection);
    return id;
}

quint64 Hec495Session::invalid(wl::Command command, const QString &why)
{
    const quint64 id = m_nextId++;
    Hec495Result r;
    r.request = uint8_t(command);
    r.status = Hec495Result::Status::NotSent;
    r.message = why;
    // Delivered from the event loop, like every other result, after the caller has the id.
    QTimer::singleShot(0, this, [this, id, r] { Q_EMIT commandFinished(id, r); });
    return id;
}

quint64 Hec495Session::setDeclination(double deg)
{
    const auto d = wl::encodeDeclination(deg);
    if (!d)
        return invalid(wl::Command::SetDeclination,
                       tr("the declination must be between -99.9 and 99.9 degrees (got %1)").arg(deg));
    return request(wl::Command::SetDeclination, QByteArray(reinterpret_cast<const char *>(d->data()), 2));
}

quint64 Hec495Session::setBaud(int baud)
{
    const auto c = wl::commands::baudCode(baud);
    if (!c)
        return invalid(wl::Command::SetBaud, tr("the HEC495 supports 2400, 4800, 9600, 19200 and 115200 baud (got %1)")
                                                 .arg(baud));
    return request(wl::Command::SetBaud, QByteArray(1, char(*c)));
}

quint64 Hec495Session::setOutputRate(int hz)
{
    const auto c = wl::commands::rateCode(hz);
    if (!c)
        return invalid(wl::Command::SetOutputRate,
                       tr("the output rate must be 0 (question/answer), 5, 10, 15, 25, 50 or 100 Hz (got %1)").arg(hz));
    return request(wl::Command::SetOutputRate, QByteArray(1, char(*c)));
}

quint64 Hec495Session::setOutputContent(wl::OutputContent content)
{
    if (uint8_t(content) > uint8_t(wl::OutputContent::Nmea0183))
        return invalid(wl::Command::SetOutputContent, tr("the output content must be 0 to 3"));
    return request(wl::Command::SetOutputContent, QByteArray(1, char(content)));
}

quint64 Hec495Session::setAddress(int address)
{
    if (address < 0 || address > 255)
        return invalid(wl::Command::SetAddress, tr("the address must be 0 to 255 (got %1)").arg(address));
    return request(wl::Command::SetAddress, QByteArray(1, char(address)));
}

quint64 Hec495Session::startCalibration(wl::CalibrationMethod method)
{
    return request(wl::Command(uint8_t(method)));
}

} // namespace imudesk::device
