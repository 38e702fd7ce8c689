#include "mcap_repair.h"

#include "format/mcap/mcap_writer.h"

#include <QCoreApplication>
#include <QFile>

#include <zstd.h>

#include <cstring>
#include <map>
#include <string>

namespace imudesk::format::mcap {

namespace {


// A little-endian reader over one record's content; every read checks the bounds.
struct Fields {
    const char *p;
    size_t n, at = 0;
    bool ok = true;
    bool need(size_t k)
    {
        if (!ok || n - at < k)
            ok = false;
        return ok;
    }
    uint64_t uint(int bytes)
    {
        uint64_t v = 0;
        if (!need(size_t(bytes)))
            return 0;
        for (int i = 0; i < bytes; ++i)
            v |= uint64_t(uint8_t(p[at + size_t(i)])) << (8 * i);
        at += size_t(bytes);
        return v;
    }
    std::string str()
    {
        const uint64_t len = uint(4);
        if (!need(size_t(len)))
            return {};
        std::string s(p + at, size_t(len));
        at += size_t(len);
        return s;
    }
    std::map<std::string, std::string> stringMap()
    {
        std::map<std::string, std::string> m;
        const uint64_t len = uint(4);
        if (!need(size_t(len)))
            return m;
        const size_t end = at + size_t(len);
        while (ok && at < end) {
            std::string k = str();
            m[k] = str();
        }
        return m;
    }
};

class Rewriter {
public:
    explicit Rewriter(McapWriter &w, RepairResult &r) : m_w(w), m_r(r) {}

    // One record (outside a chunk, or inside one).
    bool handle(uint8_t op, const char *data, size_t size)
    {
        Fields f{data, size};
        switch (op) {
        case 0x03: { // schema
            const uint16_t id = uint16_t(f.uint(2));
            const std::string name = f.str(), encoding = f.str(), def = f.str();
            if (!f.ok)
                return false;
            if (const uint16_t mine = m_w.addSchema(name, encoding, def))
                m_schemas[id] = mine;
            return true;
        }
        case 0x04: { // channel
            const uint16_t id = uint16_t(f.uint(2));
            const uint16_t schema = uint16_t(f.uint(2));
            const std::string topic = f.str(), encoding = f.str();
            const auto metadata = f.stringMap();
            if (!f.ok)
                return false;
            const auto it = m_schemas.find(schema);
            if (const uint16_t mine = m_w.addChannel(it == m_schemas.end() ? 0 : it->second, topic, encoding, metadata))
                m_channels[id] = mine;
            return true;
        }
        case 0x05: { // message
            const uint16_t channel = uint16_t(f.uint(2));
            const uint32_t sequence = uint32_t(f.uint(4));
            const uint64_t logTime = f.uint(8), publishTime = f.uint(8);
            if (!f.ok)
                return false;
            const auto it = m_channels.find(channel);
            if (it == m_channels.end())
                return true; // a message of a channel never announced: nothing can read it
            if (!m_w.write(it->second, sequence, logTime, publishTime, data + f.at, size - f.at))
                return false;
            if (m_r.messages == 0 || logTime < m_r.firstTimeNs)
                m_r.firstTimeNs = logTime;
            m_r.lastTimeNs = std::max(m_r.lastTimeNs, logTime);
            ++m_r.messages;
            return true;
        }
        case 0x06: { // chunk: its records, decompressed
            f.uint(8);
            f.uint(8);
            const uint64_t uncompressed = f.uint(8);
            f.uint(4);
            const std::string compression = f.str();
            const uint64_t length = f.uint(8);
            if (!f.ok || !f.need(size_t(length)) || uncompressed > (uint64_t(1) << 32))
                return false;
            std::string plain;
            if (compression.empty()) {
                plain.assign(data + f.at, size_t(length));
            } else if (compression == "zstd") {
                plain.resize(size_t(uncompressed));
                const size_t got = ZSTD_decompress(plain.data(), plain.size(), data + f.at, size_t(length));
                if (ZSTD_isError(got) || got != uncompressed)
                    return false;
            } else {
                return false; // lz4: not written by ImuDesk
            }
            size_t at = 0;
            while (at + 9 <= plain.size()) {
                const uint8_t inner = uint8_t(plain[at]);
                uint64_t len = 0;
                std::memcpy(&len, plain.data() + at + 1, 8);
                if (len > plain.size() - at - 9)
                    return false;
                if (!handle(inner, plain.data() + at + 9, size_t(len)))
                    return false;
                at += 9 + size_t(len);
            }
            ++m_r.chunksRead;
            return true;
        }
        case 0x09: { // attachment
            const uint64_t logTime = f.uint(8), createTime = f.uint(8);
            const std::string name = f.str(), media = f.str();
            const uint64_t len = f.uint(8);
            if (!f.ok || !f.need(size_t(len)))
                return false;
            return m_w.attach(name, media, std::string(data + f.at, size_t(len)), logTime, createTime);
        }
        case 0x0C: { // metadata
            const std::string name = f.str();
            const auto values = f.stringMap();
            return f.ok && m_w.addMetadata(name, values);
        }
        default:
            return true; // the header (written anew), indexes and the summary (recomputed)
        }
    }

private:
    McapWriter &m_w;
    RepairResult &m_r;
    std::map<uint16_t, uint16_t> m_schemas, m_channels;
};

// The messages' translation context.
class McapRepair {
    Q_DECLARE_TR_FUNCTIONS(McapRepair)
};

} // namespace

RepairResult repairMcap(const QString &in, const QString &out)
{
    QFile file(in);
    if (!file.open(QIODevice::ReadOnly)) {
        RepairResult r;
        r.error = McapRepair::tr("%1 cannot be read: %2").arg(in, file.errorString());
        return r;
    }
    RepairResult r = repairMcap(file, out);
    if (r.notMcap)
        r.error = McapRepair::tr("%1 is not an MCAP file (it does not start with MCAP's magic bytes).").arg(in);
    return r;
}

RepairResult repairMcap(QIODevice &file, const QString &out)
{
    RepairResult r;
    char magic[8];
    if (file.read(magic, 8) != 8 || std::memcmp(magic, kMagic, 8) != 0) {
        r.notMcap = true;
        r.error = McapRepair::tr("This is not an MCAP file (it does not start with MCAP's magic bytes).");
        return r;
    }
    // The header first: its profile and library carry over.
    McapWriter::Options options;
    qint64 afterHeader = 8;
    {
        char head[9];
        if (file.read(head, 9) == 9 && uint8_t(head[0]) == 0x01) {
            uint64_t len = 0;
            std::memcpy(&len, head + 1, 8);
            const QByteArray content = file.read(qint64(std::min<uint64_t>(len, 1u << 20)));
            Fields f{content.constData(), size_t(content.size())};
            const std::string profile = f.str(), library = f.str();
            if (f.ok && uint64_t(content.size()) == len) {
                options.profile = profile;
                options.library = library;
                afterHeader = 8 + 9 + qint64(len);
            }
        }
    }
    McapWriter w;
    if (!w.open(out, options)) {
        r.error = McapRepair::tr("Cannot write %1: %2").arg(out, w.error());
        return r;
    }
    Rewriter rewriter(w, r);
    if (file.isSequential() || !file.seek(afterHeader)) {
        r.error = McapRepair::tr("The file cannot be read from its start again.");
        w.abandon();
        return r;
    }
    qint64 at = afterHeader;
    const qint64 size = file.size();
    while (true) {
        char head[9];
        if (file.read(head, 9) != 9)
            break;
        const uint8_t op = uint8_t(head[0]);
        uint64_t len = 0;
        std::memcpy(&len, head + 1, 8);
        if (op == 0x0F || op == 0x02) { // data end, or a footer: the data section is over
            r.wasComplete = true;
            at = size;
            break;
        }
        if (len > uint64_t(size - at - 9))
            break; // cut short here
        const QByteArray content = file.read(qint64(len));
        if (uint64_t(content.size()) != len)
            break;
        if (!rewriter.handle(op, content.constData(), content.size())) {
            if (!w.error().isEmpty()) {
                r.error = McapRepair::tr("Writing %1 failed: %2").arg(out, w.error());
                w.abandon();
                return r;
            }
            break; // a damaged record: what came before it is kept
        }
        at += 9 + qint64(len);
    }
    r.bytesLeftOut = uint64_t(std::max<qint64>(0, size - at));
    if (!w.close()) {
        r.error = McapRepair::tr("Writing %1 failed: %2").arg(out, w.error());
        return r;
    }
    r.ok = true;
    return r;
}

} // namespace imudesk::format::mcap
