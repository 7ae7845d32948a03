// GoogleTest main for the trainer's window tests: a QApplication with the
// OpenGL 3.3 core default format the views need (run under xvfb-run).
#include "trainer_ui/app/TrainerApp.h"

#include <QApplication>

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    colonosim::app::useOpenGl33Core();
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
