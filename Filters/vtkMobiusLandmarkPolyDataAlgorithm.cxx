#include "vtkMobiusLandmarkPolyDataAlgorithm.h"

//------------------------------------------------------------------------------
void vtkMobiusLandmarkPolyDataAlgorithm::AddLandmark(vtkIdType sourceVertex, vtkIdType targetVertex)
{
  this->Landmarks.emplace_back(sourceVertex, targetVertex);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkMobiusLandmarkPolyDataAlgorithm::RemoveAllLandmarks()
{
  if (!this->Landmarks.empty())
  {
    this->Landmarks.clear();
    this->Modified();
  }
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
  os << indent << "Landmarks: " << this->Landmarks.size() << "\n";
  for (const auto& landmark : this->Landmarks)
  {
    os << indent.GetNextIndent() << landmark.first << " -> " << landmark.second << "\n";
  }
}
