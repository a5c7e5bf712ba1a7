// Placeholder so the sensor library exists until its sources land (issue 5).
