#pragma once
/// \file tab_order.h
/// The Tab order of a tab as it reads (docs/classroom.md, "Keyboard"): Qt follows the order
/// in which widgets were made, and a tab makes its canvas and tables before the rows laid out
/// above them, so Tab would jump back up the screen.
#include <initializer_list>

class QWidget;

namespace granota::ui {

/// Chains the Tab order through `parts`, in that order. A part that takes the focus with Tab
/// is one stop (a spin box, a canvas, a table); a part that does not (a panel, a compound
/// control) stands for its controls that do, in their present order.
void setTabOrderOf(std::initializer_list<QWidget*> parts);

} // namespace granota::ui
