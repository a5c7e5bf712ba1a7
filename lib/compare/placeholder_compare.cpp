// Placeholder so the compare library exists until its sources land (issue 5).
