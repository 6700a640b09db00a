#pragma once
// What a device link made of a received frame (the bridge counts each kind, docs/canbridge.md).

namespace topay::canbridge {

enum class FrameResult {
  kNotMine,    ///< Not an id of this device: another link may know it.
  kDecoded,    ///< Feedback decoded and applied.
  kMalformed,  ///< This device's id, but the frame failed to decode (DLC, range, checksum...).
  kHostFrame,  ///< A frame the host sends to this device (own frames echoed, a replayed log).
};

}  // namespace topay::canbridge
