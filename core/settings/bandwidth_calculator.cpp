#include "bandwidth_calculator.h"

#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "settings/setting_catalog.h"

namespace imudesk::settings {

namespace hp = protocol::hipnuc;

size_t BandwidthCalculator::frameBytes(hp::Message m, uint32_t hi83Map)
{
    const size_t header = hp::FrameDecoder::kHeaderSize;
    switch (m) {
    case hp::Message::HI91: return hp::Hi91::kSize + header;
    case hp::Message::HI92: return hp::Hi92::kSize + header;
    case hp::Message::HI81: return hp::Hi81::kSize + header;
    case hp::Message::HI83: {
        const auto size = hp::Hi83::payloadSize(hi83Map);
        return (size ? *size : hp::Hi83::payloadSize(hp::Hi83::kDefaultMap).value_or(0)) + header;
    }
    case hp::Message::GGA:
    case hp::Message::RMC: return 82;
    case hp::Message::SXT: return 120;
    }
    return 0;
}

const std::vector<int> &BandwidthCalculator::rateClasses()
{
    static const std::vector<int> r = {1, 2, 5, 10, 20, 50, 100, 200, 250, 500, 1000};
    return r;
}

int BandwidthCalculator::maxRateClass(hp::Message m, int baud, uint32_t hi83Map)
{
    const double bytes = double(frameBytes(m, hi83Map));
    int best = 0;
    for (int r : rateClasses())
        if (bytes * r <= capacity(baud))
            best = r;
    return best;
}

BandwidthCalculator::Result BandwidthCalculator::evaluate(const std::vector<Stream> &streams, int baud)
{
    Result res;
    res.baud = baud;
    res.capacityBytesPerSecond = capacity(baud);
    for (const Stream &s : streams) {
        if (s.rateHz <= 0)
            continue;
        Line l;
        l.stream = s;
        l.frameBytes = frameBytes(s.message, s.hi83Map);
        l.bytesPerSecond = double(l.frameBytes) * s.rateHz;
        res.bytesPerSecond += l.bytesPerSecond;
        res.lines.push_back(l);
    }
    res.load = res.capacityBytesPerSecond > 0 ? res.bytesPerSecond / res.capacityBytesPerSecond : 0;
    res.fits = res.load <= 1.0;
    res.tight = res.fits && res.load > kTightLoad;
    if (!res.fits) {
        int suggest = 0;
        for (int b : {230400, 460800, 921600})
            if (res.bytesPerSecond <= capacity(b)) {
                suggest = b;
                break;
            }
        res.warning = tr("The output needs %1 bytes/s but %2 baud carries only %3 bytes/s (%4 %): frames will be "
                         "lost. %5")
                          .arg(res.bytesPerSecond, 0, 'f', 0)
                          .arg(baud)
                          .arg(res.capacityBytesPerSecond, 0, 'f', 0)
                          .arg(res.load * 100.0, 0, 'f', 0)
                          .arg(suggest ? tr("Raise the baud rate to %1 or lower the rates.").arg(suggest)
                                       : tr("Lower the rates or turn some messages off."));
    } else if (res.tight) {
        res.warning = tr("The output uses %1 % of the link at %2 baud: little margin left, a higher baud rate is "
                         "safer.")
                          .arg(res.load * 100.0, 0, 'f', 0)
                          .arg(baud);
    }
    return res;
}

BandwidthCalculator::Result BandwidthCalculator::evaluate(const DeviceConfiguration &config, int baud)
{
    if (baud <= 0)
        baud = config.value(QStringLiteral("SERIAL.BAUD")).value_or(QStringLiteral("115200")).toInt();
    uint32_t map = hp::Hi83::kDefaultMap;
    if (const auto m = config.value(QStringLiteral("LOG.HI83.MAP")))
        map = m->mid(2).toUInt(nullptr, 16);
    std::vector<Stream> streams;
    for (const auto &d : SettingCatalog::settings()) {
        if (d.kind != SettingKind::MessageOutput)
            continue;
        const auto v = config.value(QLatin1String(d.key));
        if (!v || *v == QLatin1String("OFF") || *v == QLatin1String("ONMARK"))
            continue;
        const double period = v->toDouble();
        if (period > 0)
            streams.push_back({d.message, 1.0 / period, map});
    }
    return evaluate(streams, baud);
}

} // namespace imudesk::settings
