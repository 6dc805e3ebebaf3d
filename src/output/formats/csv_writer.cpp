// The "csv" format: the fluid particles as CSV, a file per output time (app/writers.hpp).
#include "app/writer_registry.hpp"
#include "app/writers.hpp"

namespace num::app {

namespace {

template <int Dim>
class CsvWriter final : public IWriter<Dim> {
  public:
    explicit CsvWriter(const WriterContext& context) : c_(context) {}

    void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double,
               int index) override {
        writeCsv(c_.path(c_.fileName(index, "csv")), s, fields);
    }
    std::vector<WrittenFile> files() const override {
        return {{c_.prefix + "_*.csv", "fluid particles as CSV"}};
    }

  private:
    WriterContext c_;
};

}  // namespace

void csvFormat(WriterRegistry& registry) { registry.add<CsvWriter>("csv"); }

}  // namespace num::app
