#pragma once
// Writes an MCAP file (https://mcap.dev/spec, version 0 of the format, magic "\x89MCAP0\r\n"):
// the header, schemas and channels, messages grouped in chunks (zstd-compressed or not) each
// followed by its message indexes, attachments and metadata, then the data end, a summary
// (schemas, channels, statistics, chunk, attachment and metadata indexes), the summary offsets
// and the footer. Every CRC the format has is written (data section, attachments, summary;
// a chunk's for uncompressed chunks, zstd's own content checksum in compressed ones).
//
// A chunk closes when it holds chunkBytes of records or spans chunkSpanNs of log time, and is
// then written out and flushed: a recording killed mid-run keeps every chunk closed before
// (but those still being compressed), which a reader that streams the file (no summary) reads
// up to there.
//
// With Options::background (the default), a closed chunk is compressed and written by a thread
// of the writer's own (issue 54, point 7), while the caller goes on filling the next: at most
// kChunksInFlight wait for it, then the caller waits (the memory stays bounded). Whatever is
// written outside a chunk goes through the same thread, in order.
//
// Not thread-safe for its callers: one thread calls it. Every method after a failed write
// returns false and error() says why (the disk full, the file gone).
#include "format/mcap/channel_sink.h"

#include <QFile>
#include <QString>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

struct ZSTD_CCtx_s; // zstd.h's compression context

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace imudesk::format::mcap {

// The file's first and last eight bytes.
inline constexpr char kMagic[] = "\x89MCAP0\r\n";
inline constexpr size_t kMagicSize = 8;

class McapWriter final : public ChannelSink {
public:
    enum class Compression { None, Zstd };
    struct Options {
        std::string profile = "ros2";  // the header's profile ("ros2": ROS 2 messages in CDR)
        std::string library;           // the header's library ("ImuDesk 0.x")
        Compression compression = Compression::Zstd;
        size_t chunkBytes = 1u << 20;        // uncompressed records per chunk at most (about)
        int64_t chunkSpanNs = 1'000'000'000; // a chunk never spans more log time than this
        bool background = true;              // chunks compressed and written by a thread of its own
    };
    static constexpr size_t kChunksInFlight = 2;
    McapWriter() = default;
    ~McapWriter() override;
    McapWriter(const McapWriter &) = delete;
    McapWriter &operator=(const McapWriter &) = delete;

    bool open(const QString &path, const Options &options);
    bool isOpen() const { return m_file.isOpen(); }
    // Ids from 1; 0 on failure. A schema or channel is written at once, into the open chunk if
    // there is one, before any message that uses it. The same schema, or the same channel, asked for again
    // gives the id it has.
    uint16_t addSchema(const std::string &name, const std::string &encoding, const std::string &data) override;
    uint16_t addChannel(uint16_t schemaId, const std::string &topic, const std::string &messageEncoding,
                        const StringMap &metadata = {}) override;
    // logTime, publishTime: ns (by convention since the Unix epoch).
    bool write(uint16_t channelId, uint32_t sequence, uint64_t logTime, uint64_t publishTime, const void *data,
               size_t size) override;
    // The open chunk, to append one message's bytes to, then endMessage(): no copy.
    std::string *beginMessage(uint16_t channelId, uint32_t sequence, uint64_t logTime, uint64_t publishTime) override;
    bool endMessage() override;
    bool attach(const std::string &name, const std::string &mediaType, const std::string &data, uint64_t logTime,
                uint64_t createTime);
    bool addMetadata(const std::string &name, const StringMap &values);
    // Closes the open chunk (if any) and flushes the file, once everything before is written.
    bool flush();
    // Closes the open chunk (if any); it is written (and the file flushed) in the background.
    bool endChunk();
    // Writes the summary and the footer and closes the file. Returns false (error()) when a
    // write failed, now or before.
    bool close();
    // Closes the file as it stands, without a summary (what a crash leaves; tests).
    void abandon();

    QString error() const;
    uint64_t messageCount() const { return m_messageCount; }
    // Bytes in the file so far (the summary and footer included once closed).
    uint64_t bytesWritten() const { return m_offset.load(std::memory_order_relaxed); }
    // Chunks written (once flushed or closed: every chunk).
    uint32_t chunkCount() const;

private:
    struct Schema {
        uint16_t id;
        std::string name, encoding, data;
    };
    struct Channel {
        uint16_t id, schemaId;
        std::string topic, encoding;
        StringMap metadata;
    };
    struct ChunkIndex {
        uint64_t startTime, endTime, offset, length;
        std::map<uint16_t, uint64_t> indexOffsets;
        uint64_t indexLength, compressedSize, uncompressedSize;
    };
    struct AttachmentIndex {
        uint64_t offset, length, logTime, createTime, dataSize;
        std::string name, mediaType;
    };
    struct MetadataIndex {
        uint64_t offset, length;
        std::string name;
    };

    static std::string schemaContent(const Schema &s);
    static std::string channelContent(const Channel &c);
    // What the writing side does, in order: bytes outside a chunk, or a chunk to compress and
    // write with its message indexes.
    struct Job {
        std::string bytes; // a chunk's records, or bytes to write as they are
        bool chunk = false;
        std::vector<std::vector<std::pair<uint64_t, uint64_t>>> messages; // a chunk's, by channel
        uint64_t start = 0, end = 0;
    };
    bool writeOut(const std::string &bytes); // to the file, counted in the data section's CRC
    bool putRecord(uint8_t op, const std::string &content);
    bool closeChunk();
    bool failed(const QString &what);
    bool submit(Job &&job);                  // to the writing thread, or done at once without one
    bool writeChunk(Job &job);               // compresses and writes; the writing side's
    void drain();                            // waits until the writing side has done every job
    void stopWorker();
    void workerLoop();

    QFile m_file;
    Options m_options;
    mutable std::mutex m_errorMutex;
    QString m_error;
    std::atomic<bool> m_failed{false};
    std::atomic<uint64_t> m_offset{0}; // bytes written so far
    uint32_t m_dataCrc = 0; // running CRC of the data section
    std::vector<Schema> m_schemas;
    std::vector<Channel> m_channels;
    // The open chunk: its records, and per channel (log time, offset in the records).
    std::string m_chunk;
    std::vector<std::vector<std::pair<uint64_t, uint64_t>>> m_chunkMessages; // by channel id
    uint64_t m_chunkStart = 0, m_chunkEnd = 0;
    size_t m_messageAt = 0; // where the message under way (beginMessage) starts in the chunk
    std::vector<ChunkIndex> m_chunkIndexes;
    std::vector<AttachmentIndex> m_attachments;
    std::vector<MetadataIndex> m_metadata;
    std::map<uint16_t, uint64_t> m_channelCounts;
    uint64_t m_messageCount = 0, m_firstTime = 0, m_lastTime = 0;
    std::string m_compressed; // reused between chunks
    ::ZSTD_CCtx_s *m_zstd = nullptr;
    // The writing thread and its queue (Options::background).
    std::thread m_worker;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake, m_idle;
    std::deque<Job> m_jobs;
    std::vector<Job> m_spare; // jobs done, their buffers kept for the next chunks
    bool m_busy = false, m_stop = false;
};

} // namespace imudesk::format::mcap
