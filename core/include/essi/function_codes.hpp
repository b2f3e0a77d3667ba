// The machine functions by name (ISO 6582 Annex B, and the Woyda extensions marked so), as rs274ngc names its
// G and M codes: the interpreter, the reader and the reports say `fn::kOxygenOn`, never `7`. What each code
// means in words, per dialect, is the table in essi/functions.hpp.
#pragma once

namespace essi::fn {

enum Code : int {
    kProgramStop = 0,
    kHeadOne = 1,  // a head address on a 3-axis machine
    kHeadTwo = 2,
    kIgnoreOn = 3,
    kIgnoreOff = 4,
    kRapidOn = 5,
    kRapidOff = 6,
    kOxygenOn = 7,
    kOxygenOff = 8,
    kPunchMarkingOn = 9,
    kPunchMarkingOff = 10,
    kPunchMarkingOffsetOn = 11,
    kToolOffsetOff = 12,
    kLeftBevelOn = 13,
    kLeftBevelOff = 14,
    kRightBevelOn = 15,
    kRightBevelOff = 16,
    kAccelerationControlOn = 17,  // decelerate at the end of every block, until 18
    kAccelerationControlOff = 18,
    kThreeAxisOn = 19,
    kTwoAxisOn = 20,
    kAxesNormal = 21,  // 21-28: the mapping of the tape's X/Y to the machine's axes (docs/semantics.md §7)
    kAxesMappingLast = 28,
    kKerfLeft = 29,
    kKerfRight = 30,
    kKerfOff = 38,
    kHyperthermKerfValue = 40,  // Hypertherm: 40+v, the kerf 29/30 use without a value
    kFeed = 39,
    kDwell = 41,
    kWoydaOxygenOff = 43,  // Woyda: cutting oxygen off, the preheat stays on
    kPlasmaOn = 53,
    kPlasmaOff = 54,
    kWoydaProgramZero = 62,  // Woyda: back to the program's start point on a straight line
    kCancelFunctions = 63,   // ISO: zero auxiliary function; Woyda: end of program
    kEndOfTape = 64,
    kWoydaLoopEnd = 67,  // Woyda macro files only
    kWoydaLoopStart = 68,
    kHyperthermGoHome = 79,  // Hypertherm: 79+n, home position n
    kIncremental = 81,
    kAbsolute = 82,
    kZeroOffset = 83,
    kHyperthermRepeatPointer = 97,  // Hypertherm: where 98 repeats from; 97+v a loop of v passes
    kOptionalIgnoreOn = 100,
    kOptionalIgnoreOff = 101,
    kOptionalStop = 102,
    kLineMarkingOn = 110,
    kLineMarkingOff = 111,
    kToolFiveOn = 112,
    kToolFiveOff = 113,
    kLineMarkingOffsetOn = 114,
    kToolFiveOffsetOn = 115,
    kWoydaBurnerCount = 135,
    kWoydaBurnerSpacing = 136,
    // Actions a dialect's code can stand for that no ISO code has (ESSI_ACTS_AS in function_table.def); never
    // read from a tape, never in an event.
    kFirstAction = 1000,
    kResetFunctions = kFirstAction,  // Hypertherm 63 (M31): cutting and marking tools off, kerf off
};

// The highest function code of ISO 6582 Annex B; and the codes a block can hold (at most 3 digits, ISO 3.4.1).
constexpr int kLastIsoCode = 115;
constexpr int kCodeCount = 1000;

}  // namespace essi::fn
