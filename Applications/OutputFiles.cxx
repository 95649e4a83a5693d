#include "OutputFiles.h"

#include "CorrespondencePicture.h"
#include "PublishOutputs.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkXMLPolyDataWriter.h"

#include <charconv>
#include <sys/stat.h>

namespace
{
bool Exists(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

// Anything at the name, a link to nowhere included.
bool NameTaken(const std::string& path)
{
  struct stat info;
  return lstat(path.c_str(), &info) == 0;
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

bool OutputFiles::Plan(const std::string& output, const std::string& picture, bool force,
  const std::vector<std::string>& inputs, std::string& error, bool writesCsv)
{
  std::string stem = output;
  if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, ".vtp") == 0)
  {
    stem.resize(stem.size() - 4);
  }
  // "-o sub/" would write the hidden files sub/.vtp and sub/.csv.
  const std::string name = stem.substr(stem.find_last_of('/') + 1);
  if (name.empty() || name == "." || name == "..")
  {
    error = output + ": names a folder; -o takes the outputs' name, e.g. -o " +
      (name.empty() ? stem : stem + "/") + "map";
    return false;
  }
  this->MeshPath = stem + ".vtp";
  this->CsvPath = writesCsv ? stem + ".csv" : "";
  this->PicturePath = picture;
  this->Force = force;
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
    if (NameTaken(path) && !force)
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
  // Written to memory, and the bytes by WriteFile: VTK's own file writing misses some
  // errors (a full disk) and crashes on others.
  writer->WriteToOutputStringOn();
  if (writer->Write() != 1 || writer->GetErrorCode() != 0)
  {
    error = this->MeshPath + ": cannot write the file (VTK's writer failed)";
    return false;
  }
  return this->WriteFile(this->MeshPath, writer->GetOutputString(), error);
}

bool OutputFiles::WriteCsv(vtkPolyData* correspondence, std::string& error)
{
  vtkPointData* data = correspondence->GetPointData();
  vtkDataArray* cells = data->GetArray("TargetCellId");
  vtkDataArray* weights = data->GetArray("TargetBarycentric");
  vtkDataArray* mapped = data->GetArray("MappedPoints");
  // Vertices are named by their number in the mesh files, not by their place in the maps,
  // which repairs (and the readers) may have renumbered.
  vtkDataArray* sourceIds = data->GetArray("InputPointId");
  vtkDataArray* targetIds = data->GetArray("TargetInputPointIds");
  if (!cells || !weights || !mapped || !sourceIds || !targetIds)
  {
    error = this->CsvPath + ": the map lacks the arrays of the CSV";
    return false;
  }
  auto csv = std::make_unique<SafeOutputFile>(this->CsvPath);
  if (!csv->Open(error))
  {
    return false;
  }
  std::string text = "source_vertex,target_triangle,target_vertex_0,target_vertex_1,target_vertex_2,"
                     "barycentric_0,barycentric_1,barycentric_2,mapped_x,mapped_y,mapped_z\n";
  // std::to_chars writes the shortest text that reads back to the same double (an ostream
  // at precision 17 took 4x longer for 17 digits that say no more).
  char number[32];
  auto append = [&](auto value) {
    const auto end = std::to_chars(number, number + sizeof(number), value).ptr;
    text.append(number, end);
  };
  for (vtkIdType i = 0; i < correspondence->GetNumberOfPoints(); ++i)
  {
    append(static_cast<vtkIdType>(sourceIds->GetComponent(i, 0)));
    text += ',';
    append(static_cast<vtkIdType>(cells->GetComponent(i, 0)));
    for (int k = 0; k < 3; ++k)
    {
      text += ',';
      append(static_cast<vtkIdType>(targetIds->GetComponent(i, k)));
    }
    for (vtkDataArray* array : { weights, mapped })
    {
      for (int k = 0; k < 3; ++k)
      {
        text += ',';
        append(array->GetComponent(i, k));
      }
    }
    text += '\n';
    // Written a megabyte at a time: the whole text of a large map is a lot of memory.
    if (text.size() > (1 << 20))
    {
      if (!csv->Write(text, error))
      {
        return false;
      }
      text.clear();
    }
  }
  if (!csv->Write(text, error) || !csv->Close(error))
  {
    return false;
  }
  this->Written.push_back(std::move(csv));
  return true;
}

bool OutputFiles::WritePicture(vtkPolyData* alignedSource, vtkPolyData* targetMap,
  vtkPolyData* correspondence, std::string& error)
{
  if (this->PicturePath.empty())
  {
    return true;
  }
  std::string png;
  if (!RenderCorrespondencePicture(alignedSource, targetMap, correspondence, png, error))
  {
    error = this->PicturePath + ": " + error;
    return false;
  }
  return this->WriteFile(this->PicturePath, png, error);
}

bool OutputFiles::WriteFile(const std::string& path, const std::string& bytes, std::string& error)
{
  auto file = std::make_unique<SafeOutputFile>(path);
  if (!file->Open(error) || !file->Write(bytes, error) || !file->Close(error))
  {
    return false;
  }
  this->Written.push_back(std::move(file));
  return true;
}

bool OutputFiles::Commit(std::string& error)
{
  std::vector<SafeOutputFile*> files;
  for (const auto& file : this->Written)
  {
    files.push_back(file.get());
  }
  const bool published = PublishOutputs(files, this->Force, error);
  this->Written.clear(); // what was not published is removed
  return published;
}
