#pragma once
/// \file
/// Holds the endoscope view at its frame rate by the resolution it draws at
/// (dynamic resolution). On the software rasteriser a frame's cost is mostly
/// its pixels, and the procedure loop takes a core of its own once it falls
/// behind real time (past the sigmoid on a 2-core machine), so the full
/// 640x480 view then drops to 10-18 frames/s. A trainee steering by the
/// picture needs it to move smoothly more than to be sharp: while the frames
/// come slower than kTargetRate and the draw is what holds them back, the
/// view draws at the next smaller scale (stretched over the widget,
/// smoothly filtered); while a larger scale would still make the rate, it
/// goes back up. Pure logic on the times it is given, so that it is tested
/// without a window.

#include <array>
#include <cstddef>

namespace colonosim::app {

class RenderScaleGovernor {
public:
    /// frames/s the view is held at: the trainer's target (issue: the UI's
    /// frame rate >= 30 frames/s).
    static constexpr double kTargetRate = 30.0;
    /// The scales the view may draw at, each side; each step down draws 0.64
    /// or 0.61 of the pixels of the one before. 0.5 (320x240) is the least:
    /// below it the lumen's folds are lost in the blur.
    static constexpr std::array<double, 4> kScales = {1.0, 0.8, 0.64, 0.5};
    /// s of continuous drawing over which the rate and the draw's time are
    /// judged.
    static constexpr double kWindow = 0.5;
    /// s between two frames beyond which drawing counts as stopped (paused,
    /// a dialog, the end): the window starts again with the next frame.
    static constexpr double kGap = 0.25;
    /// s after a change of scale before the next judgement (the first frames
    /// at a new scale pay for a new framebuffer).
    static constexpr double kSettle = 1.0;
    /// The share of the frame interval the draw must take to be what holds
    /// the rate back (otherwise a smaller picture would not help).
    static constexpr double kDrawShare = 0.5;

    /// A frame drawn: when its draw began and how long it took (s, on one
    /// steady clock). Returns the scale to draw the next frame at.
    double frameDrawn(double start, double drawTime);
    [[nodiscard]] double scale() const { return kScales[m_level]; }
    /// Changes of scale so far.
    [[nodiscard]] int changes() const { return m_changes; }

private:
    void restartWindow(double start, double drawTime);

    std::size_t m_level = 0;
    double m_windowStart = -1.0;  ///< start of the window's first frame, s; < 0: none yet
    double m_lastStart = -1.0;    ///< start of the last frame, s
    double m_drawSum = 0.0;       ///< s drawn in the window
    int m_frames = 0;             ///< frames in the window
    double m_settleUntil = -1.0;  ///< s: no judgement before
    int m_changes = 0;
};

}  // namespace colonosim::app
