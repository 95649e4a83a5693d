#include "vtkMobiusLandmarkPolyDataAlgorithm.h"

//------------------------------------------------------------------------------
void vtkMobiusLandmarkPolyDataAlgorithm::AddLandmark(vtkIdType sourceVertex, vtkIdType targetVertex)
{
  this->Landmarks.emplace_back(sourceVertex, targetVertex);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkMobiusLandmarkPolyDataAlgorithm::AddLandmarkValue(vtkIdType value)
{
  if (this->HasUnpairedValue)
  {
    this->HasUnpairedValue = false;
    this->AddLandmark(this->UnpairedValue, value);
    return;
  }
  this->HasUnpairedValue = true;
  this->UnpairedValue = value;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkMobiusLandmarkPolyDataAlgorithm::RemoveAllLandmarks()
{
  if (!this->Landmarks.empty() || this->HasUnpairedValue)
  {
    this->Landmarks.clear();
    this->HasUnpairedValue = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::string vtkMobiusLandmarkPolyDataAlgorithm::SettingsError()
{
  if (!this->HasUnpairedValue)
  {
    return {};
  }
  return "Landmarks holds " + std::to_string(2 * this->Landmarks.size() + 1) +
    " values, an odd number: it is a list of pairs (source point id, target point id), and "
    "the last value, " +
    std::to_string(this->UnpairedValue) + ", has no partner.";
}

//------------------------------------------------------------------------------
vtkIdType vtkMobiusLandmarkPolyDataAlgorithm::GetNumberOfLandmarks()
{
  return static_cast<vtkIdType>(this->Landmarks.size());
}

//------------------------------------------------------------------------------
vtkIdType vtkMobiusLandmarkPolyDataAlgorithm::GetLandmarkSourceVertex(vtkIdType landmark)
{
  return landmark >= 0 && landmark < this->GetNumberOfLandmarks() ? this->Landmarks[landmark].first
                                                                  : -1;
}

//------------------------------------------------------------------------------
vtkIdType vtkMobiusLandmarkPolyDataAlgorithm::GetLandmarkTargetVertex(vtkIdType landmark)
{
  return landmark >= 0 && landmark < this->GetNumberOfLandmarks()
    ? this->Landmarks[landmark].second
    : -1;
}

//------------------------------------------------------------------------------
void vtkMobiusLandmarkPolyDataAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Landmarks: " << this->Landmarks.size()
     << (this->HasUnpairedValue ? " and a value without its partner" : "") << "\n";
  for (const auto& landmark : this->Landmarks)
  {
    os << indent.GetNextIndent() << landmark.first << " -> " << landmark.second << "\n";
  }
}
