#include "hec495_session.h"

#include "device/hec495_family.h"
#include "protocol/witlink/bcd.h"


namespace imudesk::device {

namespace wl = protocol::witlink;

namespace {

Hec495Result toResult(const RequestResult &r)
{
    Hec495Result typed = r.reply.value<Hec495Result>();
    typed.status = r.status;
    typed.attempts = r.attempts;
    typed.message = r.message;
    return typed;
}

} // namespace

Hec495Session::Hec495Session(QObject *parent, std::unique_ptr<io::Transport> transport)
    : Session(std::make_unique<Hec495Family>(), std::move(transport), QStringLiteral("imudesk-hec495"),
              Hec495Family::kLineIdleMs, parent)
{
    qRegisterMetaType<Hec495Result>();
    auto *f = static_cast<Hec495Family *>(family());
    connect(this, &Session::requestEnded, this,
            [this](const RequestResult &r) { Q_EMIT commandFinished(r.id, toResult(r)); });
    connect(f, &Hec495Family::calibrationPoint, this, &Hec495Session::calibrationPoint);
    connect(f, &Hec495Family::nmeaReceived, this, &Hec495Session::nmeaReceived);
    connect(f, &Hec495Family::baudChanged, this, [this](int b) {
        m_baud = b;
        Q_EMIT baudChanged(b);
    });
    connect(f, &Hec495Family::addressChanged, this, [this](int a) {
        m_address = a;
        Q_EMIT addressChanged(a);
    });
    connect(f, &Hec495Family::streamingChanged, this, [this](bool on) {
        m_streaming = on;
        Q_EMIT streamingChanged(on);
    });
}

void Hec495Session::open(const QString &portName, int baud, int address)
{
    m_address = address;
    inFamily<Hec495Family>([address](Hec495Family &f) { f.setAddress(address); });
    openLink(portName, baud);
}

void Hec495Session::setPollingRate(int hz)
{
    inFamily<Hec495Family>([hz](Hec495Family &f) { f.setPollingRate(hz); });
}

quint64 Hec495Session::request(wl::Command command, const QByteArray &data, int timeoutMs)
{
    return submit(Hec495Family::makeRequest(uint8_t(command), data, timeoutMs));
}

quint64 Hec495Session::invalid(wl::Command command, const QString &why)
{
    Hec495Result r;
    r.request = uint8_t(command);
    return refuse(QVariant::fromValue(r), why);
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
