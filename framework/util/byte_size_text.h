#pragma once
// Memory and file sizes in messages, in the binary unit that reads best ("512.0 MiB",
// "1.3 GiB", "1.84e+06 PiB"), and the two sizes of a refusal ("would need about A, but only
// B is available") with as many digits as make A and B differ: with one decimal, 0.14 GiB
// needed against 0.12 GiB available both read "0.1 GiB", and the refusal looks absurd.
#include <string>
#include <utility>

namespace subdiv {

// One size, to about 3 significant digits.
std::string byte_size_text(double bytes);

// `need` and `have` in one unit (that of the larger), with the fewest digits that show their
// order: whenever need != have, the two texts differ. Sizes two units apart or more (PiB
// against GiB) each in their own, so that the smaller never reads "0.0 PiB".
std::pair<std::string, std::string> byte_sizes_compared(double need, double have);

}  // namespace subdiv
