#include "mcap_writer.h"

#include "format/crc32.h"

#include <zstd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <functional>

namespace imudesk::format::mcap {

static_assert(std::endian::native == std::endian::little, "message records are copied little-endian as they are");

namespace {


enum Op : uint8_t {
    OpHeader = 0x01,
    OpFooter = 0x02,
    OpSchema = 0x03,
    OpChannel = 0x04,
    OpMessage = 0x05,
    OpChunk = 0x06,
    OpMessageIndex = 0x07,
    OpChunkIndex = 0x08,
    OpAttachment = 0x09,
    OpAttachmentIndex = 0x0A,
    OpStatistics = 0x0B,
    OpMetadata = 0x0C,
    OpMetadataIndex = 0x0D,
    OpSummaryOffset = 0x0E,
    OpDataEnd = 0x0F,
};

// Little-endian field writers (the format's only byte order).
void u8(std::string &o, uint8_t v) { o.push_back(char(v)); }
void u16(std::string &o, uint16_t v)
{
    o.push_back(char(v & 0xFF));
    o.push_back(char(v >> 8));
}
void u32(std::string &o, uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        o.push_back(char((v >> (8 * i)) & 0xFF));
}
void u64(std::string &o, uint64_t v)
{
    for (int i = 0; i < 8; ++i)
        o.push_back(char((v >> (8 * i)) & 0xFF));
}
void str(std::string &o, const std::string &s)
{
    u32(o, uint32_t(s.size()));
    o += s;
}
void stringMap(std::string &o, const McapWriter::StringMap &m)
{
    std::string body;
    for (const auto &[k, v] : m) {
        str(body, k);
        str(body, v);
    }
    u32(o, uint32_t(body.size()));
    o += body;
}
// A record: opcode, the content's length, the content.
void record(std::string &o, uint8_t op, const std::string &content)
{
    u8(o, op);
    u64(o, content.size());
    o += content;
}

} // namespace

std::string McapWriter::schemaContent(const Schema &s)
{
    std::string c;
    u16(c, s.id);
    str(c, s.name);
    str(c, s.encoding);
    str(c, s.data); // bytes with a uint32 length, as a string is
    return c;
}

std::string McapWriter::channelContent(const Channel &ch)
{
    std::string c;
    u16(c, ch.id);
    u16(c, ch.schemaId);
    str(c, ch.topic);
    str(c, ch.encoding);
    stringMap(c, ch.metadata);
    return c;
}

McapWriter::~McapWriter()
{
    if (m_file.isOpen())
        close();
    stopWorker();
    ZSTD_freeCCtx(m_zstd);
}

bool McapWriter::failed(const QString &what)
{
    const std::lock_guard<std::mutex> lock(m_errorMutex);
    if (!m_failed) {
        m_error = what;
        m_failed = true;
    }
    return false;
}

QString McapWriter::error() const
{
    const std::lock_guard<std::mutex> lock(m_errorMutex);
    return m_error;
}

uint32_t McapWriter::chunkCount() const
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    return uint32_t(m_chunkIndexes.size());
}

bool McapWriter::submit(Job &&job)
{
    if (!m_worker.joinable()) { // no writing thread: at once
        const bool ok = job.chunk ? writeChunk(job) : writeOut(job.bytes);
        m_spare.push_back(std::move(job)); // emptied when it is taken again (closeChunk)
        return ok;
    }
    std::unique_lock<std::mutex> lock(m_mutex);
    m_idle.wait(lock, [this] { return m_jobs.size() < kChunksInFlight; });
    m_jobs.push_back(std::move(job));
    lock.unlock();
    m_wake.notify_one();
    return !m_failed;
}

void McapWriter::workerLoop()
{
    std::unique_lock<std::mutex> lock(m_mutex);
    for (;;) {
        m_wake.wait(lock, [this] { return m_stop || !m_jobs.empty(); });
        if (m_jobs.empty())
            return; // stopped, with nothing left to write
        Job job = std::move(m_jobs.front());
        m_jobs.pop_front();
        m_busy = true;
        lock.unlock();
        if (!m_failed) {
            if (job.chunk)
                writeChunk(job);
            else
                writeOut(job.bytes);
        }
        lock.lock();
        m_busy = false;
        if (m_spare.size() <= kChunksInFlight)
            m_spare.push_back(std::move(job)); // its buffers, for a chunk to come
        m_idle.notify_all();
    }
}

void McapWriter::drain()
{
    if (!m_worker.joinable())
        return;
    std::unique_lock<std::mutex> lock(m_mutex);
    m_idle.wait(lock, [this] { return m_jobs.empty() && !m_busy; });
}

void McapWriter::stopWorker()
{
    if (!m_worker.joinable())
        return;
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_one();
    m_worker.join();
}

bool McapWriter::open(const QString &path, const Options &options)
{
    m_options = options;
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return failed(m_file.errorString());
    std::string out(kMagic, kMagicSize);
    std::string header;
    str(header, m_options.profile);
    str(header, m_options.library);
    record(out, OpHeader, header);
    if (!writeOut(out))
        return false;
    if (m_options.background) {
        m_stop = false;
        m_worker = std::thread([this] { workerLoop(); });
    }
    return true;
}

bool McapWriter::writeOut(const std::string &bytes)
{
    if (m_failed)
        return false;
    if (m_file.write(bytes.data(), qint64(bytes.size())) != qint64(bytes.size()))
        return failed(m_file.errorString());
    m_dataCrc = format::crc32(m_dataCrc, bytes.data(), bytes.size());
    m_offset += bytes.size();
    return true;
}

uint16_t McapWriter::addSchema(const std::string &name, const std::string &encoding, const std::string &data)
{
    for (const Schema &s : m_schemas)
        if (s.name == name && s.encoding == encoding && s.data == data)
            return s.id; // one schema for every channel of the type
    if (m_failed)
        return 0;
    Schema s{uint16_t(m_schemas.size() + 1), name, encoding, data};
    if (!putRecord(OpSchema, schemaContent(s)))
        return 0;
    m_schemas.push_back(std::move(s));
    return m_schemas.back().id;
}

uint16_t McapWriter::addChannel(uint16_t schemaId, const std::string &topic, const std::string &messageEncoding,
                                const StringMap &metadata)
{
    for (const Channel &c : m_channels)
        if (c.topic == topic && c.schemaId == schemaId && c.encoding == messageEncoding && c.metadata == metadata)
            return c.id; // a topic that several writers share (/tf)
    if (m_failed)
        return 0;
    Channel c{uint16_t(m_channels.size() + 1), schemaId, topic, messageEncoding, metadata};
    if (!putRecord(OpChannel, channelContent(c)))
        return 0;
    m_channels.push_back(std::move(c));
    m_channelCounts[m_channels.back().id] = 0;
    return m_channels.back().id;
}

bool McapWriter::putRecord(uint8_t op, const std::string &content)
{
    // Inside the open chunk, where the messages that follow need it (a reader that streams the
    // file meets it first); before any chunk, in the data section.
    if (!m_chunk.empty()) {
        record(m_chunk, op, content);
        return true;
    }
    Job job;
    record(job.bytes, op, content);
    return submit(std::move(job));
}

std::string *McapWriter::beginMessage(uint16_t channelId, uint32_t sequence, uint64_t logTime, uint64_t publishTime)
{
    if (m_failed)
        return nullptr;
    if (!m_chunk.empty()
        && (m_chunk.size() >= m_options.chunkBytes || int64_t(logTime - m_chunkStart) >= m_options.chunkSpanNs
            || logTime < m_chunkStart))
        if (!closeChunk())
            return nullptr;
    if (m_chunk.empty())
        m_chunkStart = m_chunkEnd = logTime;
    if (channelId >= m_chunkMessages.size())
        m_chunkMessages.resize(size_t(channelId) + 1);
    m_chunkMessages[channelId].emplace_back(logTime, m_chunk.size());
    // The record's fixed part in one piece (little-endian host: static_assert above); its
    // length when the message is complete (endMessage).
    m_messageAt = m_chunk.size();
    char head[1 + 8 + 2 + 4 + 8 + 8];
    head[0] = char(OpMessage);
    std::memset(head + 1, 0, 8);
    std::memcpy(head + 9, &channelId, 2);
    std::memcpy(head + 11, &sequence, 4);
    std::memcpy(head + 15, &logTime, 8);
    std::memcpy(head + 23, &publishTime, 8);
    m_chunk.append(head, sizeof head);
    m_chunkStart = std::min(m_chunkStart, logTime);
    m_chunkEnd = std::max(m_chunkEnd, logTime);
    if (m_messageCount == 0) {
        m_firstTime = m_lastTime = logTime;
    } else {
        m_firstTime = std::min(m_firstTime, logTime);
        m_lastTime = std::max(m_lastTime, logTime);
    }
    ++m_messageCount;
    ++m_channelCounts[channelId]; // a map, but one small enough
    return &m_chunk;
}

bool McapWriter::endMessage()
{
    const uint64_t length = m_chunk.size() - m_messageAt - 1 - 8;
    std::memcpy(m_chunk.data() + m_messageAt + 1, &length, 8);
    return !m_failed;
}

bool McapWriter::write(uint16_t channelId, uint32_t sequence, uint64_t logTime, uint64_t publishTime,
                       const void *data, size_t size)
{
    std::string *chunk = beginMessage(channelId, sequence, logTime, publishTime);
    if (!chunk)
        return false;
    chunk->append(static_cast<const char *>(data), size);
    return endMessage();
}

bool McapWriter::closeChunk()
{
    if (m_failed)
        return false;
    if (m_chunk.empty())
        return true;
    // The chunk goes to the writing side with its message indexes; the next one is filled in a
    // spare job's buffers.
    Job job;
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        if (!m_spare.empty()) {
            job = std::move(m_spare.back());
            m_spare.pop_back();
        }
    }
    job.chunk = true;
    job.start = m_chunkStart;
    job.end = m_chunkEnd;
    std::swap(job.bytes, m_chunk);
    std::swap(job.messages, m_chunkMessages);
    m_chunk.clear(); // a spare's buffers, emptied here only; their memory stays
    if (m_chunkMessages.size() < job.messages.size())
        m_chunkMessages.resize(job.messages.size());
    for (auto &entries : m_chunkMessages)
        entries.clear();
    return submit(std::move(job));
}

bool McapWriter::writeChunk(Job &job)
{
    const std::string &chunk = job.bytes;
    const bool zstd = m_options.compression == Compression::Zstd;
    // A zstd chunk carries zstd's own checksum of its content (xxHash, a fraction of CRC-32's
    // time); the chunk's CRC is then 0, "not computed" (the specification's word for it).
    const uint32_t crc = zstd ? 0 : format::crc32(0, chunk.data(), chunk.size());
    const std::string *records = &chunk;
    if (zstd) {
        if (!m_zstd) {
            m_zstd = ZSTD_createCCtx();
            // bench_export: levels -5 to 6 differ by a few % in size (the samples' noise is what
            // does not compress), level 6 takes twice the time.
            ZSTD_CCtx_setParameter(m_zstd, ZSTD_c_compressionLevel, 1);
            ZSTD_CCtx_setParameter(m_zstd, ZSTD_c_checksumFlag, 1);
        }
        m_compressed.resize(ZSTD_compressBound(chunk.size()));
        const size_t n = ZSTD_compress2(m_zstd, m_compressed.data(), m_compressed.size(), chunk.data(), chunk.size());
        if (ZSTD_isError(n))
            return failed(QStringLiteral("zstd: %1").arg(QString::fromUtf8(ZSTD_getErrorName(n))));
        m_compressed.resize(n);
        records = &m_compressed;
    }
    const uint64_t offset = m_offset.load();
    ChunkIndex index;
    index.startTime = job.start;
    index.endTime = job.end;
    index.offset = offset;
    index.compressedSize = records->size();
    index.uncompressedSize = chunk.size();
    std::string out;
    out.reserve(records->size() + 128);
    std::string head;
    u64(head, job.start);
    u64(head, job.end);
    u64(head, chunk.size());
    u32(head, crc);
    str(head, zstd ? "zstd" : "");
    u64(head, records->size());
    u8(out, OpChunk);
    u64(out, head.size() + records->size());
    out += head;
    out += *records;
    index.length = out.size();
    // The message indexes, one per channel with messages in the chunk, after it.
    uint64_t at = offset + out.size();
    const uint64_t indexesStart = at;
    for (uint16_t channel = 0; channel < job.messages.size(); ++channel) {
        const auto &entries = job.messages[channel];
        if (entries.empty())
            continue;
        std::string content;
        u16(content, channel);
        u32(content, uint32_t(entries.size() * 16));
        for (const auto &[time, position] : entries) {
            u64(content, time);
            u64(content, position);
        }
        index.indexOffsets[channel] = at;
        const size_t before = out.size();
        record(out, OpMessageIndex, content);
        at += out.size() - before;
    }
    index.indexLength = at - indexesStart;
    if (!writeOut(out))
        return false;
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_chunkIndexes.push_back(std::move(index));
    }
    if (!m_file.flush())
        return failed(m_file.errorString());
    return true;
}

bool McapWriter::attach(const std::string &name, const std::string &mediaType, const std::string &data,
                        uint64_t logTime, uint64_t createTime)
{
    if (m_failed || !closeChunk())
        return false;
    drain(); // its offset is where the writing side has got to
    std::string content;
    u64(content, logTime);
    u64(content, createTime);
    str(content, name);
    str(content, mediaType);
    u64(content, data.size());
    content += data;
    u32(content, format::crc32(0, content.data(), content.size())); // over every field before it
    std::string out;
    record(out, OpAttachment, content);
    AttachmentIndex index{m_offset, out.size(), logTime, createTime, data.size(), name, mediaType};
    if (!writeOut(out))
        return false;
    m_attachments.push_back(std::move(index));
    return true;
}

bool McapWriter::addMetadata(const std::string &name, const StringMap &values)
{
    if (m_failed || !closeChunk())
        return false;
    drain(); // its offset is where the writing side has got to
    std::string content;
    str(content, name);
    stringMap(content, values);
    std::string out;
    record(out, OpMetadata, content);
    MetadataIndex index{m_offset, out.size(), name};
    if (!writeOut(out))
        return false;
    m_metadata.push_back(std::move(index));
    return true;
}

bool McapWriter::flush()
{
    if (!closeChunk())
        return false;
    drain();
    if (m_failed)
        return false;
    return m_file.flush() || failed(m_file.errorString());
}

bool McapWriter::endChunk()
{
    return closeChunk();
}

void McapWriter::abandon()
{
    drain();
    stopWorker();
    m_file.close();
}

bool McapWriter::close()
{
    if (!m_file.isOpen())
        return !m_failed;
    const bool closed = closeChunk();
    drain();
    stopWorker(); // the rest is written here
    if (!closed || m_failed) {
        m_file.close();
        return false;
    }
    // Data end, with the CRC of everything before it.
    std::string dataEnd;
    u32(dataEnd, m_dataCrc);
    std::string out;
    record(out, OpDataEnd, dataEnd);
    if (!writeOut(out)) {
        m_file.close();
        return false;
    }
    // The summary: each group of records, and where it starts.
    const uint64_t summaryStart = m_offset;
    std::string summary;
    struct Group {
        uint8_t op;
        uint64_t start, length;
    };
    std::vector<Group> groups;
    const auto group = [&](uint8_t op, const std::function<void()> &fill) {
        const size_t before = summary.size();
        fill();
        if (summary.size() > before)
            groups.push_back({op, summaryStart + before, summary.size() - before});
    };
    group(OpSchema, [&] {
        for (const Schema &s : m_schemas)
            record(summary, OpSchema, schemaContent(s));
    });
    group(OpChannel, [&] {
        for (const Channel &ch : m_channels)
            record(summary, OpChannel, channelContent(ch));
    });
    group(OpStatistics, [&] {
        std::string c;
        u64(c, m_messageCount);
        u16(c, uint16_t(m_schemas.size()));
        u32(c, uint32_t(m_channels.size()));
        u32(c, uint32_t(m_attachments.size()));
        u32(c, uint32_t(m_metadata.size()));
        u32(c, uint32_t(m_chunkIndexes.size()));
        u64(c, m_messageCount ? m_firstTime : 0);
        u64(c, m_messageCount ? m_lastTime : 0);
        std::string counts;
        for (const auto &[channel, n] : m_channelCounts) {
            u16(counts, channel);
            u64(counts, n);
        }
        u32(c, uint32_t(counts.size()));
        c += counts;
        record(summary, OpStatistics, c);
    });
    group(OpChunkIndex, [&] {
        for (const ChunkIndex &ci : m_chunkIndexes) {
            std::string c;
            u64(c, ci.startTime);
            u64(c, ci.endTime);
            u64(c, ci.offset);
            u64(c, ci.length);
            std::string offsets;
            for (const auto &[channel, offset] : ci.indexOffsets) {
                u16(offsets, channel);
                u64(offsets, offset);
            }
            u32(c, uint32_t(offsets.size()));
            c += offsets;
            u64(c, ci.indexLength);
            str(c, m_options.compression == Compression::Zstd ? "zstd" : "");
            u64(c, ci.compressedSize);
            u64(c, ci.uncompressedSize);
            record(summary, OpChunkIndex, c);
        }
    });
    group(OpAttachmentIndex, [&] {
        for (const AttachmentIndex &a : m_attachments) {
            std::string c;
            u64(c, a.offset);
            u64(c, a.length);
            u64(c, a.logTime);
            u64(c, a.createTime);
            u64(c, a.dataSize);
            str(c, a.name);
            str(c, a.mediaType);
            record(summary, OpAttachmentIndex, c);
        }
    });
    group(OpMetadataIndex, [&] {
        for (const MetadataIndex &m : m_metadata) {
            std::string c;
            u64(c, m.offset);
            u64(c, m.length);
            str(c, m.name);
            record(summary, OpMetadataIndex, c);
        }
    });
    const uint64_t summaryOffsetStart = summaryStart + summary.size();
    for (const Group &g : groups) {
        std::string c;
        u8(c, g.op);
        u64(c, g.start);
        u64(c, g.length);
        record(summary, OpSummaryOffset, c);
    }
    // The footer; its CRC covers the summary up to and including its summary_offset_start.
    std::string footer;
    u8(footer, OpFooter);
    u64(footer, 8 + 8 + 4);
    u64(footer, summaryStart);
    u64(footer, summaryOffsetStart);
    uint32_t crc = format::crc32(0, summary.data(), summary.size());
    crc = format::crc32(crc, footer.data(), footer.size());
    u32(footer, crc);
    std::string tail = summary + footer;
    tail.append(kMagic, kMagicSize);
    if (m_file.write(tail.data(), qint64(tail.size())) != qint64(tail.size()))
        failed(m_file.errorString());
    else
        m_offset += tail.size();
    m_file.close();
    return !m_failed;
}

} // namespace imudesk::format::mcap
