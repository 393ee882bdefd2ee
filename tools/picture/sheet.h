// Contact sheets: pictures side by side in a grid, each with a caption under it.
#pragma once

#include <string>
#include <vector>

#include "image.h"

namespace hedge::picture {

struct Panel {
  Image image;
  std::string caption;
};

//! Lays the panels out in rows of `columns` (0: all in one row), each cell as large as the largest
//! panel plus a caption strip, on `background`. Captions longer than a cell are cut with "...".
//! \throw InvalidInputError for no panels or a sheet larger than check_size allows.
Image contact_sheet(const std::vector<Panel>& panels, int columns = 0, Rgb background = {255, 255, 255});

}  // namespace hedge::picture
