#include "trainer_ui/app/KeyboardControls.h"

#include "simcore/procedure/DeviceInput.h"

#include <QObject>

#include <algorithm>
#include <array>

namespace colonosim::app {

namespace {
constexpr std::array kHeldKeys = {Qt::Key_Up, Qt::Key_Down, Qt::Key_Left, Qt::Key_Right, Qt::Key_W,
                                  Qt::Key_S,  Qt::Key_A,    Qt::Key_D,    Qt::Key_Space, Qt::Key_X};

bool isHeldKey(int key)
{
    return std::find(kHeldKeys.begin(), kHeldKeys.end(), key) != kHeldKeys.end();
}
}  // namespace

bool KeyboardControls::keyDown(int key)
{
    if (isHeldKey(key)) {
        m_held.insert(key);
        return true;
    }
    return pressButtons(key) != 0;
}

bool KeyboardControls::keyUp(int key)
{
    if (isHeldKey(key)) {
        m_held.erase(key);
        return true;
    }
    return pressButtons(key) != 0;
}

std::uint8_t KeyboardControls::pressButtons(int key)
{
    switch (key) {
    case Qt::Key_L: return procedure::kWater;
    case Qt::Key_M: return procedure::kMarkLesion;
    default: return 0;
    }
}

void KeyboardControls::setMouse(double insert, double twist)
{
    m_mouseInsert = std::clamp(insert, -1.0, 1.0);
    m_mouseTwist = std::clamp(twist, -1.0, 1.0);
}

devices::ManualControls KeyboardControls::controls() const
{
    const auto held = [this](int key) { return m_held.contains(key) ? 1.0 : 0.0; };
    devices::ManualControls out;
    out.insert = std::clamp(held(Qt::Key_Up) - held(Qt::Key_Down) + m_mouseInsert, -1.0, 1.0);
    out.twist = std::clamp(held(Qt::Key_Left) - held(Qt::Key_Right) + m_mouseTwist, -1.0, 1.0);
    out.upDown = held(Qt::Key_W) - held(Qt::Key_S);
    out.leftRight = held(Qt::Key_A) - held(Qt::Key_D);
    if (m_held.contains(Qt::Key_Space)) {
        out.buttons |= procedure::kAir;
    }
    if (m_held.contains(Qt::Key_X)) {
        out.buttons |= procedure::kSuction;
    }
    return out;
}

QString KeyboardControls::legend()
{
    return QObject::tr(
        "<b>Keys</b>: ↑/↓ insert / withdraw · ←/→ rotate the shaft · W/S up / down dial · A/D left / right "
        "dial · Space air · X suction · L lens wash · M mark a lesion · Esc end the procedure · mouse: drag "
        "with the left button to insert (up) and rotate (sideways)");
}

}  // namespace colonosim::app
