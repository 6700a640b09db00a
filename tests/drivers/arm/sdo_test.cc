// Expedited SDO (CiA 301 §7.2.4.3): download/upload requests and responses, aborts, command
// specifiers, malformed frames.
#include "drivers/arm/sdo.h"

#include <gtest/gtest.h>

namespace topay::canopen {
namespace {

TEST(SdoTest, DownloadRequestSpecifierFollowsTheSize) {
  const auto one = EncodeSdoDownloadRequest({5, {0x6060, 0}, 1, 9}, nullptr);
  ASSERT_TRUE(one);
  EXPECT_EQ(can::ToString(*one), "605#2F60600009000000");
  const auto two = EncodeSdoDownloadRequest({5, {0x1017, 0}, 2, 100}, nullptr);
  ASSERT_TRUE(two);
  EXPECT_EQ(can::ToString(*two), "605#2B17100064000000");
  const auto three = EncodeSdoDownloadRequest({5, {0x2000, 1}, 3, 0x030201}, nullptr);
  ASSERT_TRUE(three);
  EXPECT_EQ(can::ToString(*three), "605#2700200101020300");
  const auto four = EncodeSdoDownloadRequest({5, {0x1016, 1}, 4, 0x007F012C}, nullptr);
  ASSERT_TRUE(four);
  EXPECT_EQ(can::ToString(*four), "605#231610012C017F00");
}

TEST(SdoTest, EveryMessageRoundTrips) {
  for (int size : {1, 2, 3, 4}) {
    const std::uint32_t value = size == 4 ? 0xDEADBEEF : (1u << (8 * size)) - 2;
    const SdoDownloadRequest request{9, {0x60FF, 0}, size, value};
    const auto frame = EncodeSdoDownloadRequest(request, nullptr);
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->id, 0x609u);
    EXPECT_EQ(frame->dlc, 8);
    const auto back = DecodeSdoDownloadRequest(*frame, nullptr);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->node_id, 9);
    EXPECT_EQ(back->address, request.address);
    EXPECT_EQ(back->size_bytes, size);
    EXPECT_EQ(back->value, value);

    const SdoUploadResponse response{9, {0x6041, 0}, size, value};
    const auto up = EncodeSdoUploadResponse(response, nullptr);
    ASSERT_TRUE(up);
    EXPECT_EQ(up->id, 0x589u);
    EXPECT_EQ(up->data[0], 0x43 | ((4 - size) << 2));
    const auto up_back = DecodeSdoUploadResponse(*up, nullptr);
    ASSERT_TRUE(up_back);
    EXPECT_EQ(up_back->size_bytes, size);
    EXPECT_EQ(up_back->value, value);
  }
  const auto download_response = EncodeSdoDownloadResponse({9, {0x1017, 0}}, nullptr);
  ASSERT_TRUE(download_response);
  EXPECT_EQ(can::ToString(*download_response), "589#6017100000000000");
  EXPECT_TRUE(DecodeSdoDownloadResponse(*download_response, nullptr));
  const auto upload_request = EncodeSdoUploadRequest({9, {0x6041, 0}}, nullptr);
  ASSERT_TRUE(upload_request);
  EXPECT_EQ(can::ToString(*upload_request), "609#4041600000000000");
  const auto upload_back = DecodeSdoUploadRequest(*upload_request, nullptr);
  ASSERT_TRUE(upload_back);
  EXPECT_EQ(upload_back->address.index, 0x6041);
}

TEST(SdoTest, AbortsRoundTripInBothDirections) {
  const SdoAbort abort{4, {0x6060, 0}, sdo_abort::kValueRangeExceeded};
  const auto from_server = EncodeSdoAbort(abort, SdoChannel::kServerToClient, nullptr);
  ASSERT_TRUE(from_server);
  EXPECT_EQ(can::ToString(*from_server), "584#8060600030000906");
  const auto back = DecodeSdoAbort(*from_server, SdoChannel::kServerToClient, nullptr);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->abort_code, sdo_abort::kValueRangeExceeded);
  const auto from_client = EncodeSdoAbort(abort, SdoChannel::kClientToServer, nullptr);
  ASSERT_TRUE(from_client);
  EXPECT_EQ(from_client->id, 0x604u);
  EXPECT_TRUE(DecodeSdoAbort(*from_client, SdoChannel::kClientToServer, nullptr));
  EXPECT_FALSE(DecodeSdoAbort(*from_client, SdoChannel::kServerToClient, nullptr));
  EXPECT_EQ(SdoAbortCodeName(sdo_abort::kObjectDoesNotExist), "object does not exist");
  EXPECT_EQ(SdoAbortCodeName(0x12345678), "abort code 0x12345678");
}

TEST(SdoTest, ServerRepliesAndClientRequestsDispatchOnTheSpecifier) {
  const auto reply = DecodeSdoServerReply(*EncodeSdoDownloadResponse({2, {0x1017, 0}}, nullptr),
                                          nullptr);
  ASSERT_TRUE(reply);
  EXPECT_TRUE(std::holds_alternative<SdoDownloadResponse>(*reply));
  const auto abort = DecodeSdoServerReply(
      *EncodeSdoAbort({2, {0x1017, 0}, sdo_abort::kReadOnly}, SdoChannel::kServerToClient,
                      nullptr),
      nullptr);
  ASSERT_TRUE(abort);
  EXPECT_TRUE(std::holds_alternative<SdoAbort>(*abort));
  const auto upload = DecodeSdoServerReply(
      *EncodeSdoUploadResponse({2, {0x6041, 0}, 2, 0x0237}, nullptr), nullptr);
  ASSERT_TRUE(upload);
  EXPECT_EQ(std::get<SdoUploadResponse>(*upload).value, 0x0237u);
  const auto request = DecodeSdoClientRequest(
      *EncodeSdoDownloadRequest({2, {0x6060, 0}, 1, 9}, nullptr), nullptr);
  ASSERT_TRUE(request);
  EXPECT_TRUE(std::holds_alternative<SdoDownloadRequest>(*request));
  const auto read = DecodeSdoClientRequest(*EncodeSdoUploadRequest({2, {0x6041, 0}}, nullptr),
                                           nullptr);
  ASSERT_TRUE(read);
  EXPECT_TRUE(std::holds_alternative<SdoUploadRequest>(*read));
}

TEST(SdoTest, BadInputIsRejectedWithTheFrameNamed) {
  std::string error;
  EXPECT_FALSE(EncodeSdoDownloadRequest({5, {0x6060, 0}, 1, 0x100}, &error));
  EXPECT_EQ(error, "SDO download request: value 0x00000100 does not fit in 1 bytes");
  EXPECT_FALSE(EncodeSdoDownloadRequest({5, {0x6060, 0}, 5, 0}, &error));
  EXPECT_EQ(error, "SDO download request: size 5 bytes is outside 1..4 (expedited)");
  EXPECT_FALSE(EncodeSdoDownloadRequest({128, {0x6060, 0}, 1, 0}, &error));
  EXPECT_EQ(error, "SDO rx: node id 128 is outside 1..127");
  EXPECT_FALSE(EncodeSdoUploadRequest({0, {0x6041, 0}}, &error));
  // Wrong DLC.
  EXPECT_FALSE(DecodeSdoDownloadResponse(can::CanFrame::Standard(0x585, {0x60, 0x17, 0x10, 0}),
                                         &error));
  EXPECT_EQ(error, "SDO response frame '585#60171000': DLC 4, expected 8");
  // Wrong direction: a request decoded as a response.
  EXPECT_FALSE(DecodeSdoDownloadResponse(
      can::CanFrame::Standard(0x605, {0x60, 0x17, 0x10, 0, 0, 0, 0, 0}), &error));
  EXPECT_EQ(error, "SDO response frame '605#6017100000000000': id 0x605 is SDO rx, expected "
                   "SDO tx");
  // Bad command specifiers.
  EXPECT_FALSE(DecodeSdoDownloadResponse(
      can::CanFrame::Standard(0x585, {0x61, 0x17, 0x10, 0, 0, 0, 0, 0}), &error));
  EXPECT_EQ(error, "SDO response frame '585#6117100000000000': command specifier 0x61 is not a "
                   "download response (0x60)");
  EXPECT_FALSE(DecodeSdoDownloadRequest(
      can::CanFrame::Standard(0x605, {0x21, 0x00, 0x20, 0, 8, 0, 0, 0}), &error));
  EXPECT_NE(error.find("segmented transfers are not supported"), std::string::npos) << error;
  EXPECT_FALSE(DecodeSdoDownloadRequest(
      can::CanFrame::Standard(0x605, {0x40, 0x00, 0x20, 0, 0, 0, 0, 0}), &error));
  EXPECT_NE(error.find("command specifier 0x40 is not an expedited download request"),
            std::string::npos)
      << error;
  EXPECT_FALSE(DecodeSdoUploadRequest(
      can::CanFrame::Standard(0x605, {0x41, 0x41, 0x60, 0, 0, 0, 0, 0}), &error));
  EXPECT_NE(error.find("is not an upload request (0x40)"), std::string::npos);
  EXPECT_FALSE(DecodeSdoServerReply(
      can::CanFrame::Standard(0x585, {0xA0, 0, 0, 0, 0, 0, 0, 0}), &error));
  EXPECT_NE(error.find("command specifier 0xA0"), std::string::npos) << error;
  EXPECT_FALSE(DecodeSdoClientRequest(
      can::CanFrame::Standard(0x605, {0xE0, 0, 0, 0, 0, 0, 0, 0}), &error));
  EXPECT_NE(error.find("command specifier 0xE0"), std::string::npos) << error;
  EXPECT_FALSE(DecodeSdoAbort(can::CanFrame::Standard(0x585, {0x80, 0, 0, 0}),
                              SdoChannel::kServerToClient, &error));
  EXPECT_NE(error.find("DLC 4, expected 8"), std::string::npos);
}

TEST(SdoTest, SizeNotIndicatedReadsFourBytes) {
  // e = 1, s = 0 (0x22): expedited with unspecified size; read as 4 bytes.
  const auto request = DecodeSdoDownloadRequest(
      can::CanFrame::Standard(0x605, {0x22, 0x17, 0x10, 0, 0x64, 0, 0, 0}), nullptr);
  ASSERT_TRUE(request);
  EXPECT_EQ(request->size_bytes, 4);
  EXPECT_EQ(request->value, 100u);
}

}  // namespace
}  // namespace topay::canopen
