#include "stream_decoder.h"

#include "decode/can_stream_decoder.h"
#include "decode/hipnuc_stream_decoder.h"
#include "decode/witlink_stream_decoder.h"
#include "protocol/nmea/nmea_sample.h"

#include <QCoreApplication>

namespace imudesk::decode {

void StreamDecoder::nmea(const std::string &sentence, int64_t hostNs, Sink &sink) const
{
    if (!m_nmeaSamples) {
        sink.onText(TextKind::Nmea, sentence, hostNs);
        return;
    }
    if (auto s = protocol::nmea::sampleOf(sentence)) { // position, fix and time
        s->hostTimeNs = hostNs;
        Record r;
        r.family = family();
        r.type = "NMEA";
        r.unitBytes = sentence.size();
        sink.onSample(*s, r);
        sink.onText(TextKind::Nmea, sentence, hostNs);
    } else {
        sink.onText(TextKind::NmeaUndecoded, sentence, hostNs);
    }
}

std::unique_ptr<StreamDecoder> decoderFor(const std::string &linkKind)
{
    if (linkKind.empty() || linkKind == HipnucStreamDecoder::kFamily)
        return std::make_unique<HipnucStreamDecoder>();
    if (linkKind == WitlinkStreamDecoder::kFamily)
        return std::make_unique<WitlinkStreamDecoder>();
    if (linkKind == CanStreamDecoder::kFamily)
        return std::make_unique<CanStreamDecoder>();
    return nullptr;
}

std::vector<std::string> decodedFamilies()
{
    return {HipnucStreamDecoder::kFamily, WitlinkStreamDecoder::kFamily, CanStreamDecoder::kFamily};
}

int recordTagOf(const std::string &source)
{
    return HipnucStreamDecoder::tagOf(source);
}

QString unsupportedWhy(const std::string &linkKind)
{
    const QString kind = QString::fromStdString(linkKind);
    if (kind.endsWith(QLatin1String(" Modbus")))
        return QCoreApplication::translate("StreamDecoder",
                                           "The capture is of a %1 link: its registers were polled, and ImuDesk does "
                                           "not decode Modbus captures offline yet.")
            .arg(kind);
    QStringList known;
    for (const std::string &f : decodedFamilies())
        known << QString::fromStdString(f);
    return QCoreApplication::translate("StreamDecoder",
                                       "The capture is of a \"%1\" link, which this version of ImuDesk cannot decode "
                                       "(it decodes: %2). Open it with the version that recorded it.")
        .arg(kind, known.join(QStringLiteral(", ")));
}

} // namespace imudesk::decode
