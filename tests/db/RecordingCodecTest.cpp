// The stored recording round-trips bit for bit; corrupt bytes are refused with a message.
#include "db/RecordingCodec.h"

#include <gtest/gtest.h>

namespace {

using namespace colonosim;

TEST(RecordingCodec, RoundTripIsBitExact)
{
    procedure::Recording recording;
    for (int k = 0; k < 500; ++k) {
        procedure::RecordedSample s{};
        s.tip = Eigen::Vector3d::Zero();
        s.time = 0.01 * k;
        s.insertion = 1e-3 * k * k / 7.0;
        s.tip = Eigen::Vector3d(0.1 / (k + 1), -0.2 * k, 1.0 / 3.0);
        s.segment = static_cast<geometry::Segment>(k % 3);
        s.handleForce = -0.5 + k * 0.013;
        s.handleTorque = 1e-3 * (k % 11);
        s.maxWallForce = 0.7;
        s.mesenteryStrain = 0.01 * k;
        s.discomfort = k % 10;
        s.loop = static_cast<procedure::LoopKind>(k % 4);
        recording.samples.push_back(s);
    }
    recording.events.push_back({0.25, procedure::EventKind::LoopFormed, "alpha"});
    recording.events.push_back({1.5, procedure::EventKind::CecumReached, ""});
    const procedure::Recording back = db::decodeRecording(db::encodeRecording(recording));
    EXPECT_EQ(back.canonicalText(), recording.canonicalText());
}

TEST(RecordingCodec, CorruptBytesAreRefused)
{
    procedure::Recording recording;
    recording.samples.resize(10);
    std::vector<char> bytes = db::encodeRecording(recording);
    bytes.resize(bytes.size() - 3);
    EXPECT_THROW((void)db::decodeRecording(bytes), db::RecordingCodecError);
    EXPECT_THROW((void)db::decodeRecording(std::vector<char>(40, 'x')), db::RecordingCodecError);
}

}  // namespace
