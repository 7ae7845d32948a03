#pragma once
/// \file
/// The procedure's keys, as rate controls for devices::ManualInput:
///   Up / Down      insert / withdraw the shaft
///   Left / Right   rotate the shaft counter-clockwise / clockwise
///   W / S          up / down dial        A / D   left / right dial
///   Space (held)   air                   X (held) suction
///   L              lens wash             M       mark a lesion
///   Esc            end the procedure (handled by the screen)
/// Held keys give full deflection while down; L and M are presses.
/// The mouse: dragging with the left button inserts (up) and rotates (sideways).

#include "simcore/devices/ManualInput.h"

#include <QString>

#include <set>

namespace colonosim::app {

class KeyboardControls {
public:
    /// True when `key` (Qt::Key) is one of the procedure's keys; updates the held set.
    bool keyDown(int key);
    bool keyUp(int key);
    /// Buttons pressed once by `key` (lens wash, mark lesion), else 0.
    [[nodiscard]] static std::uint8_t pressButtons(int key);
    /// A mouse drag: fractions of full deflection, [-1, 1] (0, 0 when released).
    void setMouse(double insert, double twist);

    [[nodiscard]] devices::ManualControls controls() const;
    /// The key legend shown on the screen.
    [[nodiscard]] static QString legend();

private:
    std::set<int> m_held;
    double m_mouseInsert = 0.0;
    double m_mouseTwist = 0.0;
};

}  // namespace colonosim::app
