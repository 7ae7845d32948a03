// The trainer's thread handover and key mapping, without a window: the
// triple buffer gives the reader only newer values and finally the newest,
// while a writer thread publishes without waiting; the procedure's keys map
// to the manual controls as the legend says.
#include "simcore/procedure/DeviceInput.h"
#include "trainer_ui/app/KeyboardControls.h"
#include "trainer_ui/app/TripleBuffer.h"

#include <Qt>

#include <QKeySequence>

#include <ostream>

#include <gtest/gtest.h>

#include <thread>

namespace {

using namespace colonosim;

struct Payload {
    long sequence = 0;
    long copy = 0;  ///< written after `sequence`: a torn slot would differ
};

TEST(TripleBuffer, TheReaderSeesOnlyNewerWholeValuesAndFinallyTheLast)
{
    constexpr long kValues = 200000;
    app::TripleBuffer<Payload> buffer;
    std::jthread writer([&buffer] {
        for (long k = 1; k <= kValues; ++k) {
            buffer.back() = {k, k};
            buffer.publish();
        }
    });
    long last = 0;
    long fetched = 0;
    while (last < kValues) {
        if (buffer.fetch()) {
            const Payload& value = buffer.front();
            ASSERT_EQ(value.sequence, value.copy);
            ASSERT_GT(value.sequence, last);
            last = value.sequence;
            ++fetched;
        }
    }
    writer.join();
    EXPECT_EQ(last, kValues);
    EXPECT_FALSE(buffer.fetch());  // nothing newer than the last value
    EXPECT_GE(fetched, 1);
}

struct KeyCase {
    std::vector<int> held;
    double insert, twist, upDown, leftRight;
    std::uint8_t buttons;
};

/// Names a case by its keys (e.g. "Right+W"), so the test's name says what it holds.
void PrintTo(const KeyCase& c, std::ostream* out)
{
    for (size_t k = 0; k < c.held.size(); ++k) {
        *out << (k > 0 ? "+" : "") << QKeySequence(c.held[k]).toString().toStdString();
    }
}

class Keys : public ::testing::TestWithParam<KeyCase> {};

TEST_P(Keys, MapToTheManualControls)
{
    const KeyCase& c = GetParam();
    app::KeyboardControls keys;
    for (const int key : c.held) {
        EXPECT_TRUE(keys.keyDown(key)) << key;
    }
    const devices::ManualControls controls = keys.controls();
    EXPECT_EQ(controls.insert, c.insert);
    EXPECT_EQ(controls.twist, c.twist);
    EXPECT_EQ(controls.upDown, c.upDown);
    EXPECT_EQ(controls.leftRight, c.leftRight);
    EXPECT_EQ(controls.buttons, c.buttons);
    for (const int key : c.held) {
        keys.keyUp(key);
    }
    EXPECT_EQ(keys.controls().insert, 0.0);
    EXPECT_EQ(keys.controls().buttons, 0);
}

INSTANTIATE_TEST_SUITE_P(
    Table, Keys,
    ::testing::Values(KeyCase{{Qt::Key_Up}, 1.0, 0.0, 0.0, 0.0, 0},
                      KeyCase{{Qt::Key_Down}, -1.0, 0.0, 0.0, 0.0, 0},
                      KeyCase{{Qt::Key_Up, Qt::Key_Down}, 0.0, 0.0, 0.0, 0.0, 0},
                      KeyCase{{Qt::Key_Left}, 0.0, 1.0, 0.0, 0.0, 0},
                      KeyCase{{Qt::Key_Right, Qt::Key_W}, 0.0, -1.0, 1.0, 0.0, 0},
                      KeyCase{{Qt::Key_S, Qt::Key_A}, 0.0, 0.0, -1.0, 1.0, 0},
                      KeyCase{{Qt::Key_D, Qt::Key_Space}, 0.0, 0.0, 0.0, -1.0, procedure::kAir},
                      KeyCase{{Qt::Key_X}, 0.0, 0.0, 0.0, 0.0, procedure::kSuction}));

TEST(Keys, LensWashAndMarkArePressesAndOtherKeysAreNotTaken)
{
    EXPECT_EQ(app::KeyboardControls::pressButtons(Qt::Key_L), procedure::kWater);
    EXPECT_EQ(app::KeyboardControls::pressButtons(Qt::Key_M), procedure::kMarkLesion);
    app::KeyboardControls keys;
    EXPECT_FALSE(keys.keyDown(Qt::Key_Q));
    keys.setMouse(3.0, -0.5);  // a drag beyond full deflection is clamped
    EXPECT_EQ(keys.controls().insert, 1.0);
    EXPECT_EQ(keys.controls().twist, -0.5);
}

}  // namespace
