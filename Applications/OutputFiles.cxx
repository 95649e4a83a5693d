#include "OutputFiles.h"

#include "CorrespondencePicture.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <utility>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
bool Exists(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

bool SameFile(const std::string& a, const std::string& b)
{
  struct stat first, second;
  return stat(a.c_str(), &first) == 0 && stat(b.c_str(), &second) == 0 &&
    first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

std::string Folder(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}
}

OutputFiles::~OutputFiles()
{
  for (const auto& path : this->Written)
  {
    std::remove(this->Temporary(path).c_str());
  }
}

std::string OutputFiles::Temporary(const std::string& path) const
{
  return path + ".partial-" + std::to_string(getpid());
}

bool OutputFiles::Plan(const std::string& output, const std::string& picture, bool force,
  const std::vector<std::string>& inputs, std::string& error)
{
  std::string stem = output;
  if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, ".vtp") == 0)
  {
    stem.resize(stem.size() - 4);
  }
  this->MeshPath = stem + ".vtp";
  this->CsvPath = stem + ".csv";
  this->PicturePath = picture;
  for (const auto& path : { this->MeshPath, this->CsvPath, this->PicturePath })
  {
    if (path.empty())
    {
      continue;
    }
    if (!Exists(Folder(path)))
    {
      error = path + ": the folder " + Folder(path) + " does not exist";
      return false;
    }
    for (const auto& input : inputs)
    {
      if (SameFile(path, input))
      {
        error = path + ": is an input mesh; choose another output name";
        return false;
      }
    }
    if (Exists(path) && !force)
    {
      error = path + ": exists already (use --force to overwrite)";
      return false;
    }
  }
  return true;
}

bool OutputFiles::WriteMesh(vtkPolyData* correspondence, std::string& error)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(correspondence);
  // Inline binary data (appended data trips Debian's expat, README "Limitations"),
  // compressed with LZ4 rather than zlib (VTK 8.2 and later, ParaView 5.6 and later read
  // it): measured on a 17,495-vertex map, 0.25 s instead of 0.6 s on a loaded machine, the
  // file 3.7 MB instead of 2.9 MB.
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToLZ4();
  writer->SetFileName(this->Temporary(this->MeshPath).c_str());
  this->Written.push_back(this->MeshPath);
  if (writer->Write() != 1)
  {
    error = this->MeshPath + ": cannot write the file";
    return false;
  }
  return true;
}

bool OutputFiles::WriteCsv(vtkPolyData* correspondence, std::string& error)
{
  std::ofstream csv(this->Temporary(this->CsvPath));
  this->Written.push_back(this->CsvPath);
  vtkPointData* data = correspondence->GetPointData();
  vtkDataArray* cells = data->GetArray("TargetCellId");
  vtkDataArray* weights = data->GetArray("TargetBarycentric");
  vtkDataArray* mapped = data->GetArray("MappedPoints");
  // Vertices are named by their number in the mesh files, not by their place in the maps,
  // which repairs (and the readers) may have renumbered.
  vtkDataArray* sourceIds = data->GetArray("InputPointId");
  vtkDataArray* targetIds = data->GetArray("TargetInputPointIds");
  if (!csv || !cells || !weights || !mapped || !sourceIds || !targetIds)
  {
    error = this->CsvPath + ": cannot write the file";
    return false;
  }
  csv << "source_vertex,target_triangle,target_vertex_0,target_vertex_1,target_vertex_2,"
         "barycentric_0,barycentric_1,barycentric_2,mapped_x,mapped_y,mapped_z\n";
  // std::to_chars writes the shortest text that reads back to the same double (an ostream
  // at precision 17 took 4x longer for 17 digits that say no more).
  std::string line;
  char number[32];
  auto append = [&](auto value) {
    const auto end = std::to_chars(number, number + sizeof(number), value).ptr;
    line.append(number, end);
  };
  for (vtkIdType i = 0; i < correspondence->GetNumberOfPoints(); ++i)
  {
    line.clear();
    append(static_cast<vtkIdType>(sourceIds->GetComponent(i, 0)));
    line += ',';
    append(static_cast<vtkIdType>(cells->GetComponent(i, 0)));
    for (int k = 0; k < 3; ++k)
    {
      line += ',';
      append(static_cast<vtkIdType>(targetIds->GetComponent(i, k)));
    }
    for (vtkDataArray* array : { weights, mapped })
    {
      for (int k = 0; k < 3; ++k)
      {
        line += ',';
        append(array->GetComponent(i, k));
      }
    }
    line += '\n';
    csv << line;
  }
  if (!csv)
  {
    error = this->CsvPath + ": cannot write the file";
    return false;
  }
  return true;
}

bool OutputFiles::WritePicture(
  vtkPolyData* alignedSource, vtkPolyData* correspondence, std::string& error)
{
  if (this->PicturePath.empty())
  {
    return true;
  }
  this->Written.push_back(this->PicturePath);
  if (!RenderCorrespondencePicture(
        alignedSource, correspondence, this->Temporary(this->PicturePath), error))
  {
    error = this->PicturePath + ": " + error;
    return false;
  }
  return true;
}

bool OutputFiles::Commit(std::string& error)
{
  // All or nothing: a file being replaced (--force) is moved aside first, and if any rename
  // fails, the files already moved into place are taken back and the old ones restored, so
  // OUT.vtp never stays behind without its OUT.csv.
  std::vector<std::pair<std::string, std::string>> asides; // final path, where the old file is
  std::vector<std::string> placed;
  auto undo = [&]() {
    for (const auto& path : placed)
    {
      std::remove(path.c_str());
    }
    for (const auto& aside : asides)
    {
      std::rename(aside.second.c_str(), aside.first.c_str());
    }
  };
  for (const auto& path : this->Written)
  {
    struct stat information;
    if (stat(path.c_str(), &information) == 0 && S_ISREG(information.st_mode))
    {
      const std::string aside = path + ".previous-" + std::to_string(getpid());
      if (std::rename(path.c_str(), aside.c_str()) != 0)
      {
        error = path + ": cannot replace the existing file (" + std::strerror(errno) + ")";
        undo();
        return false;
      }
      asides.emplace_back(path, aside);
    }
    if (std::rename(this->Temporary(path).c_str(), path.c_str()) != 0)
    {
      error = path + ": cannot move the finished file into place (" + std::strerror(errno) + ")";
      undo();
      return false;
    }
    placed.push_back(path);
  }
  for (const auto& aside : asides)
  {
    std::remove(aside.second.c_str());
  }
  this->Written.clear();
  return true;
}
