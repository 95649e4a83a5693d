// mobius-score --dataset: the registration pipeline (exactly as mobius-register runs it) on
// pairs of a benchmark folder (Dataset.h), scored at the ground-truth samples by the
// published protocol (Filters/Core/Correspondence/SampleScore.h): per pair the mean error in
// percent of sqrt(area), against the direct and, where the dataset has it, the mirror
// ground truth; over the pairs the mean, the median and the share above 10; seconds per pair.
#ifndef DatasetScore_h
#define DatasetScore_h

/// The dataset mode's part of mobius-score --help.
extern const char* const DatasetUsage;

/// True if the arguments ask for the dataset mode (--dataset is among them).
bool IsDatasetScore(int argc, char* argv[]);

/// Runs the dataset mode; returns the exit status (0 every pair scored, 1 bad input or a
/// pair that failed, 2 usage error).
int RunDatasetScore(int argc, char* argv[]);

#endif
