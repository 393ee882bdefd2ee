// Contact sheets: pictures side by side in a grid, each with a caption under it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "image.h"

namespace hedge::picture {

struct Panel {
  Image image;
  std::string caption;
};

//! The size of the sheet of `panels` cells of cell_width x cell_height pictures in rows of `columns`
//! (0: all in one row), captions included. O(1).
//! \throw InvalidInputError for no panels, or for a sheet larger than check_size allows, giving
//!   its real size and how many panels fit; so a caller can check before drawing any panel.
void check_contact_sheet(std::size_t panels, int cell_width, int cell_height, int columns,
                         int* sheet_width = nullptr, int* sheet_height = nullptr);

//! Lays the panels out in rows of `columns` (0: all in one row), each cell as large as the largest
//! panel plus a caption strip, on `background`. Captions longer than a cell are cut with "...".
//! \throw InvalidInputError for no panels or a sheet larger than check_size allows.
Image contact_sheet(const std::vector<Panel>& panels, int columns = 0, Rgb background = {255, 255, 255});

}  // namespace hedge::picture
