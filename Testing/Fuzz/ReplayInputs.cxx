// Runs the fuzz target once on each input file, without libFuzzer: the regression test of
// builds that are not the clang sanitizer build. Arguments are files or folders (every
// regular file in a folder, in name order). A finding aborts, as under libFuzzer.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char* argv[])
{
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i)
  {
    const fs::path argument = argv[i];
    if (fs::is_directory(argument))
    {
      std::vector<fs::path> files;
      for (const auto& entry : fs::directory_iterator(argument))
      {
        if (entry.is_regular_file())
        {
          files.push_back(entry.path());
        }
      }
      std::sort(files.begin(), files.end());
      inputs.insert(inputs.end(), files.begin(), files.end());
    }
    else if (fs::is_regular_file(argument))
    {
      inputs.push_back(argument);
    }
    else
    {
      std::cerr << argument.string() << ": not a file or folder\n";
      return 1;
    }
  }
  // A replay that runs nothing checks nothing.
  if (inputs.empty())
  {
    std::cerr << "usage: " << argv[0] << " FILE_OR_FOLDER... (no inputs found)\n";
    return 1;
  }
  for (const auto& input : inputs)
  {
    std::ifstream file(input, std::ios::binary);
    const std::vector<char> bytes(
      (std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::cout << "replaying " << input.string() << " (" << bytes.size() << " bytes)" << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << inputs.size() << " inputs replayed" << std::endl;
  return 0;
}
