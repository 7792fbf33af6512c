#include "amThoraxPhantomSource.h"

#include "amProvenance.h"
#include "amThoraxPhantomModel.h"
#include "amThreading.h"

#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkShortArray.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

vtkStandardNewMacro(amThoraxPhantomSource);

namespace
{
// SplitMix64: a counter-based generator, so noise depends only on (seed, voxel), not on threads.
inline uint64_t SplitMix64(uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

int LabelOfScannerPoint(const amThoraxPhantomModel& model, const double r[3][3], const double x[3])
{
  // The anatomy at a scanner point: the model's point is the rotation's inverse (its transpose).
  const double p[3] = { r[0][0] * x[0] + r[1][0] * x[1] + r[2][0] * x[2],
    r[0][1] * x[0] + r[1][1] * x[1] + r[2][1] * x[2], r[0][2] * x[0] + r[1][2] * x[1] + r[2][2] * x[2] };
  return model.LabelAt(p);
}

inline double GaussianNoise(uint64_t seed, uint64_t index)
{
  const uint64_t a = SplitMix64(seed * 0x632BE59BD9B4E019ull + 2 * index);
  const uint64_t b = SplitMix64(seed * 0x632BE59BD9B4E019ull + 2 * index + 1);
  const double u1 = (static_cast<double>(a >> 11) + 1.0) * (1.0 / 9007199254740993.0); // (0, 1]
  const double u2 = static_cast<double>(b >> 11) * (1.0 / 9007199254740992.0);         // [0, 1)
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

// Runs body(begin, end) over [0, n) in chunks so progress can be reported from this thread.
template<typename Body>
bool ChunkedFor(amThoraxPhantomSource* self, vtkIdType n, double p0, double p1, Body&& body)
{
  const vtkIdType chunks = std::max<vtkIdType>(1, std::min<vtkIdType>(n, 20));
  for (vtkIdType c = 0; c < chunks; ++c)
  {
    const vtkIdType b = n * c / chunks, e = n * (c + 1) / chunks;
    vtkSMPTools::For(b, e, body);
    self->UpdateProgress(p0 + (p1 - p0) * static_cast<double>(c + 1) / chunks);
    if (self->GetAbortExecute())
      return false;
  }
  return true;
}

// Separable Gaussian blur of a float volume along one axis, in place (one line at a time).
void BlurAxis(std::vector<float>& data, const int dims[3], int axis, double sigmaVoxels)
{
  if (sigmaVoxels <= 0.05 || dims[axis] < 2)
    return;
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigmaVoxels)));
  std::vector<double> kernel(2 * radius + 1);
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i)
    sum += kernel[i + radius] = std::exp(-0.5 * i * i / (sigmaVoxels * sigmaVoxels));
  for (double& k : kernel)
    k /= sum;
  const vtkIdType stride[3] = { 1, dims[0], static_cast<vtkIdType>(dims[0]) * dims[1] };
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const vtkIdType lines = static_cast<vtkIdType>(dims[a1]) * dims[a2];
  vtkSMPTools::For(0, lines, [&](vtkIdType begin, vtkIdType end) {
    std::vector<float> line(static_cast<size_t>(dims[axis])); // the line before blurring
    for (vtkIdType l = begin; l < end; ++l)
    {
      const vtkIdType i1 = l % dims[a1], i2 = l / dims[a1];
      const vtkIdType base = i1 * stride[a1] + i2 * stride[a2];
      for (int i = 0; i < dims[axis]; ++i)
        line[i] = data[base + i * stride[axis]];
      for (int i = 0; i < dims[axis]; ++i)
      {
        double v = 0.0;
        for (int k = -radius; k <= radius; ++k)
        {
          const int j = std::min(dims[axis] - 1, std::max(0, i + k)); // clamp: air extends outward
          v += kernel[k + radius] * line[j];
        }
        data[base + i * stride[axis]] = static_cast<float>(v);
      }
    }
  });
}
}

amThoraxPhantomSource::amThoraxPhantomSource()
{
  amThreading::Initialize();
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
  this->Spacing[0] = this->Spacing[1] = this->Spacing[2] = 1.0;
  this->FieldOfView[0] = 320.0;
  this->FieldOfView[1] = 240.0;
  this->FieldOfView[2] = 210.0;
  this->NoiseStandardDeviation = 20.0;
  this->BlurSigma = 0.6;
  this->PartialVolumeSamples = 4;
  this->Seed = 1;
  this->BloodHounsfieldUnits = amThoraxPhantomModel::HounsfieldUnits(amThoraxPhantomModel::LeftVentricleBlood);
  this->MyocardiumHounsfieldUnits = amThoraxPhantomModel::HounsfieldUnits(amThoraxPhantomModel::Myocardium);
  this->PatientRotation[0] = this->PatientRotation[1] = this->PatientRotation[2] = 0.0;
  const amThoraxPhantomModel::Habitus habitus;
  this->FatThickness = habitus.FatThickness;
  this->HeartScale = habitus.HeartScale;
  this->HeartAngle = habitus.HeartAngle;
  this->HeartShape = habitus.HeartShape;
}

amThoraxPhantomModel amThoraxPhantomSource::Model() const
{
  amThoraxPhantomModel::Habitus habitus;
  habitus.FatThickness = this->FatThickness;
  habitus.HeartScale = this->HeartScale;
  habitus.HeartAngle = this->HeartAngle;
  habitus.HeartShape = this->HeartShape;
  return amThoraxPhantomModel(habitus);
}

void amThoraxPhantomSource::Rotation(double r[3][3]) const
{
  const double d = 3.141592653589793 / 180.0;
  const double a = this->PatientRotation[0] * d, b = this->PatientRotation[1] * d, c = this->PatientRotation[2] * d;
  const double x[3][3] = { { 1, 0, 0 }, { 0, std::cos(a), -std::sin(a) }, { 0, std::sin(a), std::cos(a) } };
  const double y[3][3] = { { std::cos(b), 0, std::sin(b) }, { 0, 1, 0 }, { -std::sin(b), 0, std::cos(b) } };
  const double z[3][3] = { { std::cos(c), -std::sin(c), 0 }, { std::sin(c), std::cos(c), 0 }, { 0, 0, 1 } };
  double yx[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      yx[i][j] = 0.0;
      for (int k = 0; k < 3; ++k)
        yx[i][j] += y[i][k] * x[k][j];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      r[i][j] = 0.0;
      for (int k = 0; k < 3; ++k)
        r[i][j] += z[i][k] * yx[k][j];
    }
}

amThoraxPhantomSource::~amThoraxPhantomSource() = default;

bool amThoraxPhantomSource::ComputeGeometry(int dims[3], double origin[3])
{
  for (int i = 0; i < 3; ++i)
  {
    if (!(this->Spacing[i] > 0.0) || !std::isfinite(this->Spacing[i]))
    {
      vtkErrorMacro("Spacing must be positive and finite; got " << this->Spacing[0] << " " << this->Spacing[1] << " "
                                                                << this->Spacing[2] << " mm.");
      return false;
    }
    if (!(this->FieldOfView[i] >= this->Spacing[i]) || !std::isfinite(this->FieldOfView[i]))
    {
      vtkErrorMacro("FieldOfView must be finite and at least one voxel along each axis; got "
        << this->FieldOfView[0] << " " << this->FieldOfView[1] << " " << this->FieldOfView[2] << " mm.");
      return false;
    }
    const double n = std::floor(this->FieldOfView[i] / this->Spacing[i] + 0.5);
    if (n > 8192)
    {
      vtkErrorMacro("FieldOfView/Spacing gives " << n << " voxels along axis " << i << " (at most 8192).");
      return false;
    }
    dims[i] = static_cast<int>(n);
    origin[i] = -0.5 * (dims[i] - 1) * this->Spacing[i]; // voxel centres symmetric about 0
  }
  return true;
}

int amThoraxPhantomSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  int dims[3];
  double origin[3];
  if (!this->ComputeGeometry(dims, origin))
    return 0;
  const int extent[6] = { 0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1 };
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    outInfo->Set(vtkDataObject::SPACING(), this->Spacing, 3);
    outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
    if (port == 0)
      vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_SHORT, 1);
    else
      vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 1);
  }
  return 1;
}

int amThoraxPhantomSource::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  int dims[3];
  double origin[3];
  if (!this->ComputeGeometry(dims, origin))
    return 0;
  vtkImageData* ct = vtkImageData::GetData(outputVector, 0);
  vtkImageData* labels = vtkImageData::GetData(outputVector, 1);
  if (!ct || !labels)
  {
    vtkErrorMacro("Missing output image.");
    return 0;
  }
  const vtkIdType nx = dims[0], ny = dims[1], nz = dims[2];
  const vtkIdType nxy = nx * ny, n = nxy * nz;
  for (vtkImageData* img : { ct, labels })
  {
    img->SetExtent(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1);
    img->SetSpacing(this->Spacing);
    img->SetOrigin(origin);
  }

  const amThoraxPhantomModel model = this->Model();
  const double* sp = this->Spacing;
  double rotation[3][3];
  this->Rotation(rotation);
  const double bloodHU = this->BloodHounsfieldUnits, myocardiumHU = this->MyocardiumHounsfieldUnits;
  const auto huOf = [bloodHU, myocardiumHU](int label) {
    if (label == amThoraxPhantomModel::LeftVentricleBlood || label == amThoraxPhantomModel::RightVentricleBlood ||
      label == amThoraxPhantomModel::Aorta)
      return bloodHU;
    if (label == amThoraxPhantomModel::Myocardium)
      return myocardiumHU;
    return amThoraxPhantomModel::HounsfieldUnits(label);
  };

  // 1. Exact labels at voxel centres.
  vtkNew<vtkUnsignedCharArray> labelArray;
  labelArray->SetName("Labels");
  labelArray->SetNumberOfTuples(n);
  unsigned char* lab = labelArray->GetPointer(0);
  this->UpdateProgress(0.0);
  if (!ChunkedFor(this, nz, 0.0, 0.35, [&](vtkIdType k0, vtkIdType k1) {
        double x[3];
        for (vtkIdType k = k0; k < k1; ++k)
          for (vtkIdType j = 0; j < ny; ++j)
            for (vtkIdType i = 0; i < nx; ++i)
            {
              x[0] = origin[0] + i * sp[0];
              x[1] = origin[1] + j * sp[1];
              x[2] = origin[2] + k * sp[2];
              lab[k * nxy + j * nx + i] = static_cast<unsigned char>(LabelOfScannerPoint(model, rotation, x));
            }
      }))
    return 0;

  // 2. Partial volume: boundary voxels average sub-voxel samples.
  std::vector<float> hu(static_cast<size_t>(n));
  const int ns = this->PartialVolumeSamples;
  if (!ChunkedFor(this, nz, 0.35, 0.75, [&](vtkIdType k0, vtkIdType k1) {
        double x[3];
        for (vtkIdType k = k0; k < k1; ++k)
          for (vtkIdType j = 0; j < ny; ++j)
            for (vtkIdType i = 0; i < nx; ++i)
            {
              const vtkIdType id = k * nxy + j * nx + i;
              const unsigned char l = lab[id];
              bool boundary = false;
              if (ns > 1)
              {
                boundary = (i > 0 && lab[id - 1] != l) || (i + 1 < nx && lab[id + 1] != l) ||
                  (j > 0 && lab[id - nx] != l) || (j + 1 < ny && lab[id + nx] != l) || (k > 0 && lab[id - nxy] != l) ||
                  (k + 1 < nz && lab[id + nxy] != l);
              }
              if (!boundary)
              {
                hu[id] = static_cast<float>(huOf(l));
                continue;
              }
              double sum = 0.0;
              for (int c = 0; c < ns; ++c)
                for (int b = 0; b < ns; ++b)
                  for (int a = 0; a < ns; ++a)
                  {
                    x[0] = origin[0] + (i + (a + 0.5) / ns - 0.5) * sp[0];
                    x[1] = origin[1] + (j + (b + 0.5) / ns - 0.5) * sp[1];
                    x[2] = origin[2] + (k + (c + 0.5) / ns - 0.5) * sp[2];
                    sum += huOf(LabelOfScannerPoint(model, rotation, x));
                  }
              hu[id] = static_cast<float>(sum / (ns * ns * ns));
            }
      }))
    return 0;

  // 3. Scanner point-spread function.
  if (this->BlurSigma > 0.0)
    for (int axis = 0; axis < 3; ++axis)
    {
      BlurAxis(hu, dims, axis, this->BlurSigma / sp[axis]);
      this->UpdateProgress(0.75 + 0.05 * (axis + 1));
    }

  // 4. Noise, rounding to 16-bit HU.
  vtkNew<vtkShortArray> ctArray;
  ctArray->SetName("CT");
  ctArray->SetNumberOfTuples(n);
  short* out = ctArray->GetPointer(0);
  const double sigma = this->NoiseStandardDeviation;
  const uint64_t seed = static_cast<uint64_t>(static_cast<uint32_t>(this->Seed));
  if (!ChunkedFor(this, nz, 0.9, 1.0, [&](vtkIdType k0, vtkIdType k1) {
        for (vtkIdType id = k0 * nxy; id < k1 * nxy; ++id)
        {
          double v = hu[id];
          if (sigma > 0.0)
            v += sigma * GaussianNoise(seed, static_cast<uint64_t>(id));
          v = std::min(32767.0, std::max(-32768.0, std::floor(v + 0.5)));
          out[id] = static_cast<short>(v);
        }
      }))
    return 0;

  ct->GetPointData()->SetScalars(ctArray);
  labels->GetPointData()->SetScalars(labelArray);

  vtkNew<vtkStringArray> names;
  names->SetName("LabelNames");
  for (int l = 0; l < amThoraxPhantomModel::NumberOfLabels; ++l)
    names->InsertNextValue(amThoraxPhantomModel::LabelName(l));
  std::ostringstream params;
  params << "Spacing=" << sp[0] << "," << sp[1] << "," << sp[2] << " FieldOfView=" << this->FieldOfView[0] << ","
         << this->FieldOfView[1] << "," << this->FieldOfView[2] << " NoiseStandardDeviation=" << sigma
         << " BlurSigma=" << this->BlurSigma << " PartialVolumeSamples=" << ns << " Seed=" << this->Seed
         << " BloodHounsfieldUnits=" << bloodHU << " MyocardiumHounsfieldUnits=" << myocardiumHU
         << " PatientRotation=" << this->PatientRotation[0] << "," << this->PatientRotation[1] << ","
         << this->PatientRotation[2];
  const amThoraxPhantomModel::Habitus usual;
  if (this->FatThickness != usual.FatThickness || this->HeartScale != usual.HeartScale ||
    this->HeartAngle != usual.HeartAngle)
    params << " FatThickness=" << this->FatThickness << " HeartScale=" << this->HeartScale
           << " HeartAngle=" << this->HeartAngle;
  if (this->HeartShape != usual.HeartShape)
    params << " HeartShape=" << this->HeartShape;
  for (vtkImageData* img : { ct, labels })
  {
    img->GetFieldData()->AddArray(names);
    amProvenance::Record(img, nullptr, "amThoraxPhantomSource", params.str());
  }
  this->UpdateProgress(1.0);
  return 1;
}

int amThoraxPhantomSource::GetLabelAtPoint(double x, double y, double z)
{
  const double p[3] = { x, y, z };
  double r[3][3];
  this->Rotation(r);
  return LabelOfScannerPoint(this->Model(), r, p);
}

double amThoraxPhantomSource::GetExactVolume(int label)
{
  return this->Model().ExactVolume(label);
}

double amThoraxPhantomSource::GetBodyVolume()
{
  return this->Model().BodyVolume();
}

const char* amThoraxPhantomSource::GetLabelName(int label)
{
  return amThoraxPhantomModel::LabelName(label);
}

int amThoraxPhantomSource::GetNumberOfLabels()
{
  return amThoraxPhantomModel::NumberOfLabels;
}

void amThoraxPhantomSource::ModelToScanner(const double model[3], double scanner[3])
{
  double r[3][3];
  this->Rotation(r);
  const double m[3] = { model[0], model[1], model[2] }; // model and scanner may be one array
  for (int i = 0; i < 3; ++i)
    scanner[i] = r[i][0] * m[0] + r[i][1] * m[1] + r[i][2] * m[2];
}

void amThoraxPhantomSource::HeartToScanner(const double defaultHeart[3], double scanner[3])
{
  double frame[3], model[3];
  amThoraxPhantomModel().WorldToHeartFrame(defaultHeart, frame);
  this->Model().HeartFrameToWorld(frame, model);
  this->ModelToScanner(model, scanner);
}

void amThoraxPhantomSource::GetOrganCenter(int label, double center[3])
{
  double c[3];
  this->Model().GetOrganCenter(label, c);
  this->ModelToScanner(c, center);
}

void amThoraxPhantomSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Spacing: " << this->Spacing[0] << " " << this->Spacing[1] << " " << this->Spacing[2] << " mm\n";
  os << indent << "FieldOfView: " << this->FieldOfView[0] << " " << this->FieldOfView[1] << " " << this->FieldOfView[2]
     << " mm\n";
  os << indent << "FatThickness: " << this->FatThickness << " mm\n";
  os << indent << "HeartScale: " << this->HeartScale << "\n";
  os << indent << "HeartAngle: " << this->HeartAngle << " degrees\n";
  os << indent << "HeartShape: " << (this->HeartShape == VENTRICLES ? "VENTRICLES" : "ELLIPSOIDAL") << "\n";
  os << indent << "NoiseStandardDeviation: " << this->NoiseStandardDeviation << " HU\n";
  os << indent << "BlurSigma: " << this->BlurSigma << " mm\n";
  os << indent << "PartialVolumeSamples: " << this->PartialVolumeSamples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "BloodHounsfieldUnits: " << this->BloodHounsfieldUnits << "\n";
  os << indent << "MyocardiumHounsfieldUnits: " << this->MyocardiumHounsfieldUnits << "\n";
  os << indent << "PatientRotation: " << this->PatientRotation[0] << " " << this->PatientRotation[1] << " "
     << this->PatientRotation[2] << " degrees\n";
}
