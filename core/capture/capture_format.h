#pragma once
// Byte layout of an ImuDesk capture file (see docs/FILE_FORMATS.md, "Capture file format"). All
// integers little-endian.
//
//   file    = file-header chunk*
//   header  = "IMUDCAP1" | u16 version (1) | u16 0 | u32 body length L (<= 1 MiB)
//             | L bytes body (CaptureHeader::encodeBody) | u32 CRC-32 of everything before it
//   chunk   = u32 magic "CHNK" | u16 kind | u16 flags (0) | u32 payload length N (1..16 MiB)
//             | i64 host monotonic ns | i64 host wall clock us since 1970 UTC
//             | N payload bytes | u32 CRC-32 of everything before it in the chunk
//
// A reader accepts chunks up to the first one that is incomplete (the writer was killed,
// the cable was pulled, the disk filled) and never trusts a chunk whose CRC fails.
#include "capture/capture_header.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace imudesk::capture {

inline constexpr char kMagic[8] = {'I', 'M', 'U', 'D', 'C', 'A', 'P', '1'};
inline constexpr uint16_t kVersion = 1;
inline constexpr size_t kFileHeaderFixed = 16; // magic, version, reserved, body length
inline constexpr uint32_t kChunkMagic = 0x4B4E4843u; // "CHNK"
inline constexpr size_t kChunkHeaderSize = 28;
inline constexpr size_t kChunkTrailerSize = 4;
inline constexpr size_t kChunkOverhead = kChunkHeaderSize + kChunkTrailerSize;
inline constexpr uint32_t kMaxChunkPayload = 16u << 20;

enum ChunkKind : uint16_t {
    ChunkReceived = 0, // bytes received from the device, exactly as they arrived
    ChunkLineIdle = 1, // the session found the line idle here and released held bytes (payload: one 0 byte)
    ChunkSent = 2,     // bytes the host wrote to the device (a request), at the time it wrote them
    // An imported vendor CSV's cells that the frame of the next received chunk cannot give back
    // (decode::vendor_csv::encodeCells: "pps_sync_stamp=12,incli_x=..." as lines); its vendor CSV export
    // writes them back. Readers that do not know it pass over it.
    ChunkVendorCells = 3,
};

std::vector<uint8_t> encodeFileHeader(const CaptureHeader &header);
// Appends one complete chunk (header, payload, CRC) to out; n must be 1..kMaxChunkPayload.
void appendChunk(std::vector<uint8_t> &out, ChunkKind kind, int64_t monotonicNs, int64_t wallUs, const uint8_t *data,
                 size_t n);

} // namespace imudesk::capture
