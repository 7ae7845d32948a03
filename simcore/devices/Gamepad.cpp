#include "simcore/devices/Gamepad.h"

#include <SDL.h>

namespace colonosim::devices {

namespace {
double axis(SDL_GameController* c, SDL_GameControllerAxis a)
{
    return static_cast<double>(SDL_GameControllerGetAxis(c, a)) / 32767.0;
}
}  // namespace

ManualControls controlsFrom(const GamepadState& s)
{
    ManualControls c;
    c.insert = -s.leftY;  // stick pushed away (SDL: negative y) pushes the shaft in
    c.twist = -s.leftX;   // stick left twists counter-clockwise
    c.upDown = -s.rightY;
    c.leftRight = -s.rightX;
    unsigned bits = 0;
    bits |= s.a ? static_cast<unsigned>(procedure::kAir) : 0U;
    bits |= s.b ? static_cast<unsigned>(procedure::kWater) : 0U;
    bits |= s.x ? static_cast<unsigned>(procedure::kSuction) : 0U;
    bits |= s.y ? static_cast<unsigned>(procedure::kMarkLesion) : 0U;
    c.buttons = static_cast<std::uint8_t>(bits);
    return c;
}

Gamepad::Gamepad(int index)
{
    if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) {
        throw DeviceError(std::string("gamepad: SDL's game-controller subsystem is unavailable: ") +
                          SDL_GetError());
    }
    const int joysticks = SDL_NumJoysticks();
    int controllers = 0;
    for (int i = 0; i < joysticks; ++i) {
        controllers += SDL_IsGameController(i) == SDL_TRUE ? 1 : 0;
    }
    if (controllers == 0) {
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
        throw DeviceError("gamepad: no game controller is connected (SDL sees " + std::to_string(joysticks) +
                          " joystick(s))");
    }
    if (index < 0 || index >= controllers) {
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
        throw DeviceError("gamepad.index = " + std::to_string(index) + " is outside [0, " +
                          std::to_string(controllers - 1) + "]: " + std::to_string(controllers) +
                          " game controller(s) connected");
    }
    for (int i = 0, seen = 0; i < joysticks; ++i) {
        if (SDL_IsGameController(i) == SDL_TRUE && seen++ == index) {
            m_controller = SDL_GameControllerOpen(i);
            break;
        }
    }
    if (m_controller == nullptr) {
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
        throw DeviceError(std::string("gamepad: cannot open controller: ") + SDL_GetError());
    }
    const char* name = SDL_GameControllerName(static_cast<SDL_GameController*>(m_controller));
    m_name = name != nullptr ? name : "gamepad";
}

Gamepad::~Gamepad()
{
    if (m_controller != nullptr) {
        SDL_GameControllerClose(static_cast<SDL_GameController*>(m_controller));
    }
    SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
}

GamepadState Gamepad::read()
{
    SDL_GameControllerUpdate();
    auto* c = static_cast<SDL_GameController*>(m_controller);
    GamepadState s;
    s.leftX = axis(c, SDL_CONTROLLER_AXIS_LEFTX);
    s.leftY = axis(c, SDL_CONTROLLER_AXIS_LEFTY);
    s.rightX = axis(c, SDL_CONTROLLER_AXIS_RIGHTX);
    s.rightY = axis(c, SDL_CONTROLLER_AXIS_RIGHTY);
    s.a = SDL_GameControllerGetButton(c, SDL_CONTROLLER_BUTTON_A) != 0;
    s.b = SDL_GameControllerGetButton(c, SDL_CONTROLLER_BUTTON_B) != 0;
    s.x = SDL_GameControllerGetButton(c, SDL_CONTROLLER_BUTTON_X) != 0;
    s.y = SDL_GameControllerGetButton(c, SDL_CONTROLLER_BUTTON_Y) != 0;
    return s;
}

procedure::InputSample GamepadOperator::next(const procedure::ProcedureLoop& loop)
{
    return m_input.update(controlsFrom(m_pad.read()), loop.trace().loopStep);
}

}  // namespace colonosim::devices
