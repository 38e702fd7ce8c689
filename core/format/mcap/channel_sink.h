#pragma once
// Where SampleChannels (sample_channels.h) puts a device's schemas, channels and messages: an
// MCAP file (McapWriter) or the live bridge's clients (bridge/foxglove_bridge.h). The same
// topics, schemas and encodings reach both, so a tool that opens a recording reads the live
// stream the same way.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

namespace imudesk::format::mcap {

class ChannelSink {
public:
    using StringMap = std::map<std::string, std::string>;
    virtual ~ChannelSink() = default;
    // Ids from 1; 0 when it could not be added. The same schema, or the same channel, asked for
    // again gives the id it has.
    virtual uint16_t addSchema(const std::string &name, const std::string &encoding, const std::string &data) = 0;
    virtual uint16_t addChannel(uint16_t schemaId, const std::string &topic, const std::string &messageEncoding,
                                const StringMap &metadata = {}) = 0;
    // logTime, publishTime: ns since the Unix epoch. False when the sink failed for good.
    virtual bool write(uint16_t channelId, uint32_t sequence, uint64_t logTime, uint64_t publishTime,
                       const void *data, size_t size) = 0;
    // A message encoded in place (an MCAP file's chunk): the buffer its bytes are appended to,
    // then endMessage(); null when this sink takes finished messages only (write), or failed.
    virtual std::string *beginMessage(uint16_t, uint32_t, uint64_t, uint64_t) { return nullptr; }
    virtual bool endMessage() { return false; }
};

} // namespace imudesk::format::mcap
