#pragma once

#include <string_view>

// The words APCS shows: those of the 1989 session, byte for byte as the thesis' figures 4.2.1–4.2.7
// give them (SPEC §3), and the few of our own (marked).
namespace apcs::words {

inline constexpr std::string_view ask_key1 = "Please keyin the KEY1 filename!";
inline constexpr std::string_view ask_key2 = "Please keyin the KEY2 filename!";
inline constexpr std::string_view adding_points_done = "Adding_Points work is done.";
inline constexpr std::string_view must_input_two_files = "You must Input 2 Files to adjust animation path:";
// "ani1.dat and aniN.dat." / "ani1.dat contained the first graphic point to adjust its path." …
inline constexpr std::string_view contained_first = " contained the first graphic point to adjust its path.";
inline constexpr std::string_view contained_last = " contained the last graphic point to adjust its path.";
inline constexpr std::string_view ask_view = "Please input the VIEWER'S direction and delay time:";
inline constexpr std::string_view ask_view_values = "THETA ,PHI & delay-time value.";
inline constexpr std::string_view ask_path_file = "Please keyin the anix.dat filename";
inline constexpr std::string_view ask_path_file_purpose = "to adjust the point's animating path!";
inline constexpr std::string_view slope_range = "The Starting and Ending Points' slope ranged from 0 to 1.";
inline constexpr std::string_view ask_slopes = "Please input the slope : DS[0] ,DD[N]";
inline constexpr std::string_view choose_control = "8 : Global Control    2 : Local Control";
inline constexpr std::string_view ask_again = "Adjust the path again ? (Y/N)";
inline constexpr std::string_view ask_next_path = "Press 'Y' to adjust the next path !";
inline constexpr std::string_view ask_stop = "Press <ENTER> to Stop the work !";
inline constexpr std::string_view fitting = "Please wait a moment! Surface Fitting is working now .....";
inline constexpr std::string_view fitting_done = "Surface-Fitting work is done.";
inline constexpr std::string_view ask_draw = "Press any key to draw the animation effect!";

// Ours: graphics-mode key help and messages.
inline constexpr std::string_view pick_first = "Local: 4/6 move the arrow, Enter picks the FIRST control point";
inline constexpr std::string_view pick_last = "Local: 4/6 move the arrow, Enter picks the LAST control point";
// On the staff while a pinned reference (C) is the path as it still is: its dashes are under the curve.
inline constexpr std::string_view reference_under_curve = "A lies under the curve until the curve moves (C unpins)";
inline constexpr std::string_view staff_keys = "4/6 step  J/L 3 steps  Enter accept  Esc keep";
inline constexpr std::string_view animation_keys = "Esc stop  Space pause  R replay";
inline constexpr std::string_view animation_done = "Press any key to see all frames";
inline constexpr std::string_view overlay_done = "Press any key to end APCS";
inline constexpr std::string_view frames_freeze = "frames will freeze";
inline constexpr std::string_view quit_question = "Quit without saving this path ? (Y/N)";
// Esc on an empty line at a text prompt (SPEC §7.3): every file is written there, nothing is lost.
inline constexpr std::string_view quit_apcs_question = "Quit APCS ? (Y/N)";
// After a staff line's name, for a path of two control points.
inline constexpr std::string_view no_interior_points = " acts at interior control points: add one with W at the 8/2 choice";

} // namespace apcs::words
